package org.parpe.gui.view3d;

import java.util.ArrayList;
import java.util.List;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.snapshot.SimSnapshot;

/**
 * TrackRobot's readout of a run in the 3D view: where the centre of mass was when the run
 * started, and its path since (the trail drawn on the ground). A new run is told by the time
 * going back. UI thread only.
 */
final class RunTrail {
    /** The most points of the trail kept (the oldest go first). */
    static final int TRAIL_POINTS = 4000;

    private final List<Vec3> trail = new ArrayList<>();
    private Vec3 start;
    private double lastTime = Double.NaN;

    /** Forgets the run (another script was opened). */
    void clear() {
        lastTime = Double.NaN;
        start = null;
        trail.clear();
    }

    /**
     * Adds {@code snap}'s centre of mass to the trail (once per simulated time, and only when it
     * moved); returns whether it starts a new run (the time went back, or the first picture).
     */
    boolean add(SimSnapshot snap) {
        if (snap.time() == lastTime) {
            return false;
        }
        boolean newRun = Double.isNaN(lastTime) || snap.time() < lastTime;
        lastTime = snap.time();
        Vec3 c = snap.centerOfMass();
        if (!c.isFinite()) {
            return false;
        }
        if (newRun) {
            start = c;
            trail.clear();
        }
        Vec3 end = trail.isEmpty() ? null : trail.get(trail.size() - 1);
        if (end == null || Math.hypot(c.x() - end.x(), c.y() - end.y()) > 0.005) {
            if (trail.size() == TRAIL_POINTS) {
                trail.subList(0, TRAIL_POINTS / 4).clear();
            }
            trail.add(c);
        }
        return newRun;
    }

    /** The distance of {@code snap}'s centre of mass from where the run started, in metres (NaN before a run). */
    double distanceFromStart(SimSnapshot snap) {
        if (snap == null || start == null || !snap.centerOfMass().isFinite()) {
            return Double.NaN;
        }
        Vec3 c = snap.centerOfMass();
        return Math.hypot(c.x() - start.x(), c.y() - start.y());
    }

    /** The points of the trail, oldest first. */
    List<Vec3> points() {
        return trail;
    }
}
