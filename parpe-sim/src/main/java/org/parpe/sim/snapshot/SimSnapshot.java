package org.parpe.sim.snapshot;

import java.util.Collections;
import java.util.List;
import java.util.SortedMap;
import java.util.SortedSet;
import java.util.TreeMap;
import java.util.TreeSet;
import org.parpe.sim.geom.Vec3;

/**
 * An immutable picture of the simulated world at one instant, safe to hand to another thread
 * (the IDE draws it on its own timer).
 *
 * @param time           simulated time, seconds
 * @param bodies         every rigid piece, in configuration order
 * @param contacts       contact points of the last physics sub-step
 * @param centerOfMass   the robot's centre of mass, world frame, metres
 * @param measuredAngles joint angle of every segment, degrees, by logical module ID
 * @param targetAngles   the angle each servo is driving to, degrees, by logical module ID
 * @param limpModules    the modules whose servo is limp (back-drivable)
 * @param scenery        the world's fixed solids ({@link org.parpe.sim.geom.PartKind#SCENERY}, module −1, part the
 *                       element) and the pieces of its movable objects ({@link org.parpe.sim.geom.PartKind#OBJECT},
 *                       part the object's name); empty on the flat floor
 */
public record SimSnapshot(double time, List<SimBody> bodies, List<SimContact> contacts,
                          Vec3 centerOfMass, SortedMap<Integer, Double> measuredAngles,
                          SortedMap<Integer, Double> targetAngles, SortedSet<Integer> limpModules,
                          List<SimBody> scenery) {

    /** A snapshot on the flat floor (no scenery). */
    public SimSnapshot(double time, List<SimBody> bodies, List<SimContact> contacts, Vec3 centerOfMass,
                       SortedMap<Integer, Double> measuredAngles, SortedMap<Integer, Double> targetAngles,
                       SortedSet<Integer> limpModules) {
        this(time, bodies, contacts, centerOfMass, measuredAngles, targetAngles, limpModules, List.of());
    }

    public SimSnapshot {
        scenery = List.copyOf(scenery);
        bodies = List.copyOf(bodies);
        contacts = List.copyOf(contacts);
        measuredAngles = Collections.unmodifiableSortedMap(new TreeMap<>(measuredAngles));
        targetAngles = Collections.unmodifiableSortedMap(new TreeMap<>(targetAngles));
        limpModules = Collections.unmodifiableSortedSet(new TreeSet<>(limpModules));
    }

    /** The measured angle of module {@code id}, degrees, or NaN if the robot has no such module. */
    public double angle(int id) {
        Double a = measuredAngles.get(id);
        return a == null ? Double.NaN : a;
    }
}
