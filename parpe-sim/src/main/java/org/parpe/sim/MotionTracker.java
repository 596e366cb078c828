package org.parpe.sim;

import org.ode4j.math.DMatrix3C;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.internal.Assembly;
import org.parpe.sim.internal.PhysicsWorld;

/**
 * Follows the centre of mass and the robot's tilt for {@link SimMetrics}: the root part's tilt,
 * or for a rolling robot (a wheel or a loop, {@link org.parpe.sim.internal.Assembly.Axle}) its
 * axle's, which rolling does not turn: twice the angle the axle tipped from its starting slope,
 * so that a wheel lying flat reads 180° as a walker on its back does.
 */
final class MotionTracker {
    private final PhysicsWorld world;
    private final double[] com = new double[3];
    private final double[] start = new double[3];
    private final double[] upLocal = new double[3];
    private Assembly.Axle axle;
    /** The axle's slope at the start, radians above the horizontal. */
    private double axleSlope;
    private final double[] markedCom = new double[3];
    private double startTime;
    private double maxTilt;
    private double markedTime = Double.NaN;
    private double markedMaxTilt;

    MotionTracker(PhysicsWorld world) {
        this.world = world;
        this.axle = world.assembly().axle();
        reset();
    }

    /** Starts measuring from the current state. */
    void reset() {
        world.centerOfMass(start);
        System.arraycopy(start, 0, com, 0, 3);
        startTime = world.time();
        maxTilt = 0;
        markedTime = Double.NaN;
        if (axle != null) {
            axleSlope = axleSlope();
            return;
        }
        DMatrix3C r = world.pieceRotation(world.assembly().rootPiece());
        // The root's local axis that points up now: the third row of its rotation.
        for (int i = 0; i < 3; i++) {
            upLocal[i] = r.get(2, i);
        }
    }

    /** Updates after a tick. */
    void update() {
        world.centerOfMass(com);
        if (axle != null) {
            maxTilt = Math.max(maxTilt, Math.min(Math.PI, 2 * Math.abs(axleSlope() - axleSlope)));
            return;
        }
        DMatrix3C r = world.pieceRotation(world.assembly().rootPiece());
        double z = r.get(2, 0) * upLocal[0] + r.get(2, 1) * upLocal[1] + r.get(2, 2) * upLocal[2];
        maxTilt = Math.max(maxTilt, Math.acos(Math.max(-1, Math.min(1, z))));
    }

    /**
     * The robot arms a latch (PARSL.md §14) and may close a loop and roll: from now on it is judged
     * as a loop is, by its root segment's hinge axis, which curling up and rolling leave level.
     */
    void mayRoll() {
        if (axle != null) {
            return;
        }
        for (Assembly.Hinge h : world.assembly().hinges()) {
            if (h.base() == world.assembly().rootPiece()) {
                axle = new Assembly.Axle(h.base(), new Vec3(0, 0, 1));
                axleSlope = axleSlope();
                return;
            }
        }
    }

    /** The rolling robot's axle's slope now, radians above the horizontal (rolling about it leaves it alone). */
    private double axleSlope() {
        DMatrix3C r = world.pieceRotation(axle.piece());
        Vec3 a = axle.local();
        double z = r.get(2, 0) * a.x() + r.get(2, 1) * a.y() + r.get(2, 2) * a.z();
        return Math.asin(Math.max(-1, Math.min(1, z)));
    }

    /** The current centre of mass (a live buffer: read, do not keep). */
    double[] com() {
        return com;
    }

    /** The largest tilt of the root so far, radians. */
    double maxTilt() {
        return maxTilt;
    }

    /** Copies the current centre of mass into {@code out[at..at+2]}. */
    void centerOfMass(double[] out, int at) {
        System.arraycopy(com, 0, out, at, 3);
    }

    /**
     * Remembers the current state as that of the tick being emitted, before the plant moves on:
     * the metrics of a run end at its last tick, not one physics step later.
     */
    void mark() {
        System.arraycopy(com, 0, markedCom, 0, 3);
        markedTime = world.time();
        markedMaxTilt = maxTilt;
    }

    /** From the start to the last marked tick, or to now when no tick was marked (stepped by hand). */
    SimMetrics metrics() {
        boolean marked = !Double.isNaN(markedTime);
        double[] end = marked ? markedCom : com;
        double duration = (marked ? markedTime : world.time()) - startTime;
        double dx = end[0] - start[0];
        double dy = end[1] - start[1];
        double d = Math.hypot(dx, dy);
        return new SimMetrics(duration, d, dx, dy, duration > 0 ? d / duration : 0,
                Math.toDegrees(marked ? markedMaxTilt : maxTilt));
    }
}
