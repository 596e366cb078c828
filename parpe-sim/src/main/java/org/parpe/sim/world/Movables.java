package org.parpe.sim.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.lang.Numbers;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.geom.Geo;

/** The movable objects of a world file: chips, balls, cups and levers. */
final class Movables {
    /** Gap between a resting object and the floor at the start, m. */
    private static final double CLEARANCE = 0.0005;
    /** Wall pieces of a cup. */
    private static final int CUP_WALLS = 12;

    private final WorldReader r;
    private final Scenery scenery;

    /**
     * The kinds of movable object, named as their elements. Each switch over a kind is exhaustive,
     * so a new kind does not compile until it says its attributes and how it is built.
     */
    enum Kind {
        CHIP, BALL, CUP, LEVER;

        /** The element's name: {@code <chip>}. */
        String xml() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }

        /** The kind of element {@code name}, or null. */
        static Kind of(String name) {
            for (Kind k : values()) {
                if (k.xml().equals(name)) {
                    return k;
                }
            }
            return null;
        }
    }

    Movables(WorldReader r, Scenery scenery) {
        this.r = r;
        this.scenery = scenery;
    }

    void add(Kind k, Map<String, String> a, SourcePos at) {
        String kind = k.xml();
        boolean ok = switch (k) {
            case CHIP -> r.known(a, at, kind, "name", "x", "y", "radius", "thickness", "mass", "friction");
            case BALL -> r.known(a, at, kind, "name", "x", "y", "radius", "mass", "friction");
            case CUP -> r.known(a, at, kind, "name", "x", "y", "radius", "height", "mass", "friction");
            case LEVER -> r.known(a, at, kind, "name", "x", "y", "yaw", "height", "length", "width", "thickness",
                    "axis", "turn", "stiffness", "press-angle", "max-angle", "mass", "friction");
        };
        if (!ok || !r.required(a, at, kind, "name", "x", "y") || !r.unique(a.get("name"), at)) {
            return;
        }
        double x = r.coord(a, "x", 0, at);
        double y = r.coord(a, "y", 0, at);
        double friction = r.friction(a, at);
        String name = a.get("name");
        switch (k) {
            case CHIP -> {
                double t = r.length(a, "thickness", 0.0033, at);
                scenery.addObject(new World.MovableObject(name, kind, List.of(piece(new BodyShape.Cylinder(
                        r.length(a, "radius", 0.02, at), t))), new Vec3(x, y, t / 2 + CLEARANCE), Mat3.IDENTITY,
                        mass(a, 0.01, at), friction));
            }
            case BALL -> {
                double radius = r.length(a, "radius", 0.03, at);
                scenery.addObject(new World.MovableObject(name, kind, List.of(piece(new BodyShape.Sphere(radius))),
                        new Vec3(x, y, radius + CLEARANCE), Mat3.IDENTITY, mass(a, 0.05, at), friction));
            }
            case CUP -> cup(name, x, y, a, at, friction);
            case LEVER -> lever(name, x, y, a, at, friction);
            default -> throw new AssertionError(k); // the switch expression above names every kind
        }
    }

    private double mass(Map<String, String> a, double fallback, SourcePos at) {
        return r.mass(a, fallback, at);
    }

    private static World.Piece piece(BodyShape shape) {
        return new World.Piece(shape, Vec3.ZERO, Mat3.IDENTITY);
    }

    /** An open cup: a base disc and a ring of thin wall boards; its frame's origin is mid-height. */
    private void cup(String name, double x, double y, Map<String, String> a, SourcePos at, double friction) {
        double radius = r.length(a, "radius", 0.04, at);
        double h = r.length(a, "height", 0.06, at);
        double w = Math.min(0.004, radius / 4);
        if (!(h > w)) {
            // the wall boards would have no height left above the base (ODE refuses the box)
            r.error(at, org.parpe.core.text.Msg.CUP_HEIGHT, Numbers.brief(w), a.get("height"));
            return;
        }
        List<World.Piece> pieces = new ArrayList<>();
        pieces.add(new World.Piece(new BodyShape.Cylinder(radius, w), new Vec3(0, 0, -h / 2 + w / 2), Mat3.IDENTITY));
        double board = radius * Math.tan(Math.PI / CUP_WALLS);
        for (int i = 0; i < CUP_WALLS; i++) {
            double angle = 2 * Math.PI * i / CUP_WALLS;
            double c = radius - w / 2;
            pieces.add(new World.Piece(new BodyShape.Box(w / 2, board, (h - w) / 2),
                    new Vec3(c * Math.cos(angle), c * Math.sin(angle), w / 2), Geo.rotZ(angle)));
        }
        scenery.addObject(new World.MovableObject(name, "cup", pieces, new Vec3(x, y, h / 2 + CLEARANCE),
                Mat3.IDENTITY, mass(a, 0.03, at), friction));
    }

    /**
     * A lever arm from its pivot ({@code x}, {@code y}, {@code height}) along {@code yaw}, on a
     * hinge about the vertical (a press turns it {@code left} or {@code right} seen from above) or
     * about the horizontal across the arm (a press pushes its free end down).
     */
    private void lever(String name, double x, double y, Map<String, String> a, SourcePos at, double friction) {
        double yaw = r.num(a, "yaw", 0, at, -360, 360);
        double len = r.length(a, "length", 0.1, at);
        String axisName = a.getOrDefault("axis", "vertical");
        String turn = a.getOrDefault("turn", "left");
        if (!axisName.equals("vertical") && !axisName.equals("horizontal")) {
            r.error(at, org.parpe.core.text.Msg.BAD_AXIS, axisName);
        }
        if (!turn.equals("left") && !turn.equals("right")) {
            r.error(at, org.parpe.core.text.Msg.BAD_TURN, turn);
        }
        double rad = Math.toRadians(yaw);
        Vec3 along = new Vec3(Math.cos(rad), Math.sin(rad), 0);
        Vec3 axis = axisName.equals("horizontal") ? Geo.cross(along, new Vec3(0, 0, -1))
                : new Vec3(0, 0, turn.equals("right") ? -1 : 1);
        double press = r.num(a, "press-angle", 20, at, 1, 90);
        double max = r.num(a, "max-angle", 45, at, 1, 170);
        if (max < press) {
            r.error(at, org.parpe.core.text.Msg.MAX_BELOW_MIN, "max-angle", "press-angle", a.getOrDefault("press-angle", "20"), max);
        }
        Vec3 pivot = new Vec3(x, y, r.num(a, "height", 0.03, at, 0, WorldReader.FAR));
        BodyShape arm = new BodyShape.Box(len / 2, r.length(a, "width", 0.02, at) / 2,
                r.length(a, "thickness", 0.01, at) / 2);
        scenery.addObject(new World.MovableObject(name, "lever",
                List.of(new World.Piece(arm, new Vec3(len / 2, 0, 0), Mat3.IDENTITY)), pivot, WorldReader.yaw(yaw),
                mass(a, 0.02, at), friction));
        scenery.addLever(new World.Lever(name, scenery.object(name), pivot, axis,
                r.num(a, "stiffness", 0.2, at, 0, 1000), Math.toRadians(press), Math.toRadians(max)));
    }
}
