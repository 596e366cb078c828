package org.parpe.sim.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.parpe.core.diag.SourcePos;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.geom.Geo;

/** The solids and movable objects of a world file, element by element, with the rubble generated. */
final class Scenery {
    /** Most rubble pieces one {@code <rubble>} may make. */
    static final int MAX_RUBBLE = 2000;

    private final WorldReader r;
    private final List<World.Solid> solids = new ArrayList<>();
    private final List<World.MovableObject> objects = new ArrayList<>();
    private final List<World.Lever> levers = new ArrayList<>();

    Scenery(WorldReader r) {
        this.r = r;
    }

    List<World.Solid> solids() {
        return solids;
    }

    List<World.MovableObject> objects() {
        return objects;
    }

    List<World.Lever> levers() {
        return levers;
    }

    /** The index of the object called {@code name}, or −1. */
    int object(String name) {
        for (int i = 0; i < objects.size(); i++) {
            if (objects.get(i).name().equals(name)) {
                return i;
            }
        }
        return -1;
    }

    /** The index of the lever called {@code name}, or −1. */
    int lever(String name) {
        for (int i = 0; i < levers.size(); i++) {
            if (levers.get(i).name().equals(name)) {
                return i;
            }
        }
        return -1;
    }

    void solid(String kind, Map<String, String> a, SourcePos at) {
        switch (kind) {
            case "box", "step" -> box(kind, a, at);
            case "ramp" -> ramp(a, at);
            case "wall" -> wall(a, at);
            case "cylinder" -> cylinder(a, at);
            default -> rubble(a, at);
        }
    }

    /** A box standing on the floor (a box may float {@code z} above it). */
    private void box(String kind, Map<String, String> a, SourcePos at) {
        boolean isBox = kind.equals("box");
        String[] keys = isBox ? new String[] {"x", "y", "z", "length", "width", "height", "yaw", "friction"}
                : new String[] {"x", "y", "length", "width", "height", "yaw", "friction"};
        if (!r.known(a, at, kind, keys) || !r.required(a, at, kind, "x", "y", "length", "width", "height")) {
            return;
        }
        double h = r.length(a, "height", 0.05, at);
        double z = isBox ? r.num(a, "z", 0, at, -WorldReader.FAR, WorldReader.FAR) : 0;
        solids.add(new World.Solid(kind, WorldReader.box(r.length(a, "length", 1, at) / 2, r.length(a, "width", 1, at) / 2,
                h / 2), WorldReader.v(r.coord(a, "x", 0, at), r.coord(a, "y", 0, at), z + h / 2),
                WorldReader.yaw(yawOf(a, at)), r.friction(a, at)));
    }

    /**
     * A slab whose top face rises from the floor at ({@code x}, {@code y}) along {@code yaw} at
     * {@code slope} degrees for {@code length} metres (measured along the slope).
     */
    private void ramp(Map<String, String> a, SourcePos at) {
        if (!r.known(a, at, "ramp", "x", "y", "length", "width", "slope", "yaw", "thickness", "friction")
                || !r.required(a, at, "ramp", "x", "y", "length", "width", "slope")) {
            return;
        }
        double len = r.length(a, "length", 1, at);
        double t = r.length(a, "thickness", 0.05, at);
        double slope = Math.toRadians(r.num(a, "slope", 10, at, 0.1, 60));
        Mat3 turn = Geo.mul(WorldReader.yaw(yawOf(a, at)), Geo.axisAngle(new Vec3(0, 1, 0), -slope));
        // the top face's centre, then half the thickness down along the face's normal
        Vec3 topCentre = Geo.mul(turn, new Vec3(len / 2, 0, 0));
        Vec3 centre = Geo.add(topCentre, Geo.mul(turn, new Vec3(0, 0, -t / 2)));
        solids.add(new World.Solid("ramp", WorldReader.box(len / 2, r.length(a, "width", 1, at) / 2, t / 2),
                Geo.add(centre, WorldReader.v(r.coord(a, "x", 0, at), r.coord(a, "y", 0, at), 0)), turn,
                r.friction(a, at)));
    }

    /** A wall on the floor from ({@code x0}, {@code y0}) to ({@code x1}, {@code y1}). */
    private void wall(Map<String, String> a, SourcePos at) {
        if (!r.known(a, at, "wall", "x0", "y0", "x1", "y1", "height", "thickness", "friction")
                || !r.required(a, at, "wall", "x0", "y0", "x1", "y1")) {
            return;
        }
        double x0 = r.coord(a, "x0", 0, at);
        double y0 = r.coord(a, "y0", 0, at);
        double x1 = r.coord(a, "x1", 0, at);
        double y1 = r.coord(a, "y1", 0, at);
        double len = Math.hypot(x1 - x0, y1 - y0);
        if (len == 0) {
            r.error(at, org.parpe.core.text.Msg.WALL_ENDS, a.get("x0"), a.get("y0"));
            return;
        }
        double h = r.length(a, "height", 0.2, at);
        double t = r.length(a, "thickness", 0.02, at);
        solids.add(new World.Solid("wall", WorldReader.box(len / 2, t / 2, h / 2),
                WorldReader.v((x0 + x1) / 2, (y0 + y1) / 2, h / 2),
                WorldReader.yaw(Math.toDegrees(Math.atan2(y1 - y0, x1 - x0))), r.friction(a, at)));
    }

    private void cylinder(Map<String, String> a, SourcePos at) {
        if (!r.known(a, at, "cylinder", "x", "y", "z", "radius", "height", "friction")
                || !r.required(a, at, "cylinder", "x", "y", "radius", "height")) {
            return;
        }
        double h = r.length(a, "height", 0.1, at);
        solids.add(new World.Solid("cylinder", new BodyShape.Cylinder(r.length(a, "radius", 0.05, at), h),
                WorldReader.v(r.coord(a, "x", 0, at), r.coord(a, "y", 0, at),
                        r.num(a, "z", 0, at, -WorldReader.FAR, WorldReader.FAR) + h / 2), Mat3.IDENTITY,
                r.friction(a, at)));
    }

    /**
     * {@code count} boxes of random size ({@code min-size}…{@code max-size} along each side),
     * position in the region, yaw and tilt (up to {@code max-tilt} degrees), half sunk into the
     * floor: the same {@code seed} gives the same pile.
     */
    private void rubble(Map<String, String> a, SourcePos at) {
        if (!r.known(a, at, "rubble", "x0", "y0", "x1", "y1", "count", "seed", "min-size", "max-size", "max-tilt",
                "friction") || !r.required(a, at, "rubble", "count")) {
            return;
        }
        World.Region region = r.region("rubble", a, at);
        int count = (int) r.whole(a, "count", 0, at, 1, MAX_RUBBLE);
        long seed = r.whole(a, "seed", 1, at, 0, Long.MAX_VALUE >> 11);
        double min = r.length(a, "min-size", 0.02, at);
        double max = r.length(a, "max-size", 0.08, at);
        double tilt = r.num(a, "max-tilt", 20, at, 0, 90);
        if (max < min) {
            r.error(at, org.parpe.core.text.Msg.MAX_BELOW_MIN, "max-size", "min-size", a.get("min-size"), a.get("max-size"));
            return;
        }
        double friction = r.friction(a, at);
        SplittableRandom rnd = new SplittableRandom(seed);
        for (int i = 0; i < count; i++) {
            double sx = min + (max - min) * rnd.nextDouble();
            double sy = min + (max - min) * rnd.nextDouble();
            double sz = min + (max - min) * rnd.nextDouble();
            double x = region.x0() + (region.x1() - region.x0()) * rnd.nextDouble();
            double y = region.y0() + (region.y1() - region.y0()) * rnd.nextDouble();
            Mat3 turn = Geo.rollPitchYaw(tilt * (2 * rnd.nextDouble() - 1), tilt * (2 * rnd.nextDouble() - 1),
                    360 * rnd.nextDouble());
            solids.add(new World.Solid("rubble", WorldReader.box(sx / 2, sy / 2, sz / 2), new Vec3(x, y, sz / 4),
                    turn, friction));
        }
    }

    private double yawOf(Map<String, String> a, SourcePos at) {
        return r.num(a, "yaw", 0, at, -360, 360);
    }

    void movable(Movables.Kind kind, Map<String, String> a, SourcePos at) {
        new Movables(r, this).add(kind, a, at);
    }

    void addObject(World.MovableObject o) {
        objects.add(o);
    }

    void addLever(World.Lever l) {
        levers.add(l);
    }
}
