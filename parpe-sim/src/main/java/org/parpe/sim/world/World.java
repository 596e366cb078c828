package org.parpe.sim.world;

import java.util.List;
import java.util.Optional;
import org.parpe.core.diag.SourcePos;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;

/**
 * A world for the simulator, read from a world file (format in {@code docs/simulator.md}):
 * the floor, fixed solids, objects the robot can move, regions that score, where the robot
 * starts and for how long it may run. Immutable; rubble is already generated.
 *
 * @param name          a name for messages (the file)
 * @param floorFriction Coulomb friction between anything and the floor
 * @param timeLimit     simulated seconds a run lasts unless the command line says otherwise
 * @param start         where the robot's root part starts
 * @param arena         the region the robot must stay in (null: unbounded)
 * @param solids        fixed solids (boxes, ramps, steps, walls, cylinders, rubble)
 * @param objects       movable objects (chips, balls, cups, lever arms)
 * @param levers        hinged lever arms with a return spring (their arm is also in {@code objects})
 * @param zones         named goal and delivery zones
 * @param checkpoints   checkpoints in the order the robot should pass them
 * @param scoring       how a run in this world is scored
 */
public record World(String name, double floorFriction, double timeLimit, Start start, Region arena,
                    List<Solid> solids, List<MovableObject> objects, List<Lever> levers, List<Region> zones,
                    List<Region> checkpoints, Scoring scoring) {

    /** Friction of the floor unless the world gives another. */
    public static final double DEFAULT_FLOOR_FRICTION = 0.6;

    public World {
        solids = List.copyOf(solids);
        objects = List.copyOf(objects);
        levers = List.copyOf(levers);
        zones = List.copyOf(zones);
        checkpoints = List.copyOf(checkpoints);
    }

    /** The zone called {@code zoneName}. */
    public Optional<Region> zone(String zoneName) {
        return zones.stream().filter(z -> z.name().equals(zoneName)).findFirst();
    }

    /**
     * Where the robot starts: its root part at ({@code x}, {@code y}), turned by {@code yaw}
     * and tilted by {@code pitch} (degrees, about the robot's own y after the yaw), then lowered
     * so its lowest point rests {@code z} metres above the floor.
     */
    public record Start(double x, double y, double z, double yaw, double pitch) {
        /** At the origin, unturned, on the floor. */
        public static final Start ORIGIN = new Start(0, 0, 0, 0, 0);
    }

    /** An axis-aligned rectangle on the floor, from ({@code x0}, {@code y0}) to ({@code x1}, {@code y1}). */
    public record Region(String name, double x0, double y0, double x1, double y1, SourcePos at) {
        /** Whether the point ({@code x}, {@code y}) lies inside. */
        public boolean contains(double x, double y) {
            return x >= x0 && x <= x1 && y >= y0 && y <= y1;
        }

        /** The centre x. */
        public double cx() {
            return (x0 + x1) / 2;
        }

        /** The centre y. */
        public double cy() {
            return (y0 + y1) / 2;
        }
    }

    /**
     * A fixed solid.
     *
     * @param kind     the element it came from (box, ramp, step, wall, cylinder, rubble)
     * @param shape    box or upright cylinder
     * @param position centre, metres
     * @param rotation orientation (columns are the local axes)
     * @param friction Coulomb friction of its surface
     */
    public record Solid(String kind, BodyShape shape, Vec3 position, Mat3 rotation, double friction) {
    }

    /**
     * One shape of a movable object, placed in the object's frame.
     *
     * @param shape    its shape
     * @param offset   its centre in the object's frame
     * @param rotation its orientation in the object's frame
     */
    public record Piece(BodyShape shape, Vec3 offset, Mat3 rotation) {
    }

    /**
     * An object the robot can push: one rigid body of one or more pieces.
     *
     * @param name     its name (scoring counts objects by name prefix)
     * @param kind     chip, ball, cup or lever
     * @param pieces   its shapes, in its own frame
     * @param position where its frame starts, metres
     * @param rotation how its frame starts turned
     * @param mass     kilograms, spread over the pieces by volume
     * @param friction Coulomb friction of its surface
     */
    public record MovableObject(String name, String kind, List<Piece> pieces, Vec3 position, Mat3 rotation,
                                double mass, double friction) {
        public MovableObject {
            pieces = List.copyOf(pieces);
        }
    }

    /**
     * A lever: a movable arm (object number {@code object}) on a hinge fixed to the world, held
     * against its rest stop by a torsion spring; pressing it past {@code pressAngle} counts a press.
     *
     * @param name       its name
     * @param object     index of its arm in {@link World#objects()}
     * @param pivot      a point on the hinge axis, metres
     * @param axis       the hinge axis (unit); a press turns the arm about it by a positive angle
     * @param stiffness  spring stiffness, N·m per radian
     * @param pressAngle how far (radians) the arm must turn to count a press; it must come back
     *                   below half of it before the next press counts
     * @param maxAngle   the far stop, radians
     */
    public record Lever(String name, int object, Vec3 pivot, Vec3 axis, double stiffness, double pressAngle,
                        double maxAngle) {
    }

    /**
     * How a run is scored; each part adds its points, and a disqualified run scores 0.
     *
     * @param goal         reaching a zone (null: not scored)
     * @param pathPerMetre points per metre of progress along start → checkpoints (0: not scored)
     * @param deliveries   objects brought into zones
     * @param presses      lever presses
     * @param maxTiltDeg   the robot is disqualified if its root tilts further (NaN: never)
     * @param leaveArena   the robot is disqualified if its centre of mass leaves the arena
     */
    public record Scoring(Goal goal, double pathPerMetre, List<Delivery> deliveries, List<Presses> presses,
                          double maxTiltDeg, boolean leaveArena) {
        public Scoring {
            deliveries = List.copyOf(deliveries);
            presses = List.copyOf(presses);
        }
    }

    /** Reaching {@code zone} (the robot's centre of mass inside): {@code points}, plus {@code perSecondLeft} for each second of the time limit left. */
    public record Goal(Region zone, double points, double perSecondLeft) {
    }

    /** {@code points} for each object whose name starts with {@code objects} lying in {@code zone} at the end. */
    public record Delivery(Region zone, String objects, double points) {
    }

    /** {@code points} for each press of lever number {@code lever}. */
    public record Presses(int lever, double points) {
    }
}
