package org.parpe.sim.world;

import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.lang.Numbers;
import org.parpe.core.xml.FlatXmlFile;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.geom.Geo;

/**
 * Reads a world file (format in {@code docs/simulator.md}) with the project's flat XML reader,
 * so its input limits and {@code FILE:LINE:COL} messages are those of robot configurations.
 * Reports every problem it finds; then returns {@code null}.
 */
public final class WorldReader {
    /** Largest coordinate or length accepted, m. */
    static final double FAR = 1000;
    /**
     * Smallest length accepted, m (1 mm): nothing a robot meets is smaller, and ODE's mass check
     * fails on a movable object far smaller (a cup or chip of radius 1e-9 m ended in an
     * internal error).
     */
    static final double SMALL = 0.001;
    /** Smallest and largest mass of a movable object, kg (1 g … 1 t). */
    static final double LIGHT = 0.001;
    static final double HEAVY = 1000;
    private static final List<String> SOLIDS = List.of("box", "step", "ramp", "wall", "cylinder", "rubble");
    private static final List<String> SCORES = List.of("goal", "path-score", "deliver", "press", "disqualify");
    /** Every element of a world file, in the order the "expected …" message names them. */
    static final List<String> ELEMENTS = elements();

    /** How a script names the world it is written for: {@code <?parpe world="../worlds/rubble.xml"?>}. */
    private static final java.util.regex.Pattern DECLARED =
            java.util.regex.Pattern.compile("<\\?parpe\\s+world\\s*=\\s*\"([^\"]+)\"\\s*\\?>");

    /**
     * The world file that the script {@code script} with text {@code text} says it is written for
     * ({@code <?parpe world="FILE"?>}, a path relative to the script's folder, before the root
     * element), or null when it names none. Not checked to exist or be a world.
     */
    public static Path declaredBy(Path script, String text) {
        java.util.regex.Matcher m = DECLARED.matcher(text);
        int root = text.indexOf("<program");
        if (!m.find() || root >= 0 && m.start() > root) {
            return null;
        }
        try {
            Path dir = script.toAbsolutePath().getParent();
            return (dir == null ? Path.of(m.group(1)) : dir.resolve(m.group(1))).normalize();
        } catch (java.nio.file.InvalidPathException e) {
            return null;
        }
    }

    private final FlatXmlFile xml;
    private final Scenery scenery;
    private final List<World.Region> zones = new ArrayList<>();
    private final List<World.Region> checkpoints = new ArrayList<>();
    private final List<Map.Entry<FlatXmlFile.Element, String>> scoreElements = new ArrayList<>();
    private final Set<String> names = new HashSet<>();
    private World.Start start;
    private World.Region arena;
    private double floorFriction;

    private WorldReader(FlatXmlFile xml) {
        this.xml = xml;
        this.scenery = new Scenery(this);
    }

    /** Reads {@code path}; returns {@code null} after reporting errors to {@code diags}. */
    public static World read(Path path, DiagnosticSink diags) {
        FlatXmlFile xml = FlatXmlFile.read(path, Message.of(Msg.FILE_WORLD), "world", Message.of(Msg.EXPECTED_WORLD), diags);
        if (xml.root() == null) {
            return null;
        }
        WorldReader r = new WorldReader(xml);
        Map<String, String> ra = xml.rootAttributes();
        xml.known(ra, Set.of("time-limit", "floor-friction"), "world", xml.root());
        double timeLimit = xml.number(ra, "time-limit", 30, xml.root(), false, 0.01, 1e6);
        r.floorFriction = r.num(ra, "floor-friction", World.DEFAULT_FLOOR_FRICTION, xml.root(), 0, 10);
        for (FlatXmlFile.Element e : xml.children()) {
            r.element(e);
        }
        World.Scoring scoring = new ScoringReader(r, r.zones, r.scenery).read(r.scoreElements);
        if (scoring.leaveArena() && r.arena == null) {
            xml.error(xml.root(), Msg.LEAVE_ARENA_NEEDS_ARENA);
        }
        if (!xml.ok()) {
            return null;
        }
        return new World(path.toString(), r.floorFriction, timeLimit, r.start == null ? World.Start.ORIGIN : r.start,
                r.arena, r.scenery.solids(), r.scenery.objects(), r.scenery.levers(), r.zones, r.checkpoints, scoring);
    }

    private void element(FlatXmlFile.Element e) {
        Map<String, String> a = e.attributes();
        SourcePos at = e.at();
        switch (e.name()) {
            case "start" -> start(a, at);
            case "arena" -> {
                if (arena != null) {
                    error(at, Msg.ELEMENT_GIVEN_TWICE, "arena");
                } else if (known(a, at, "arena", "x0", "y0", "x1", "y1")) {
                    arena = region("arena", a, at);
                }
            }
            case "zone" -> {
                if (known(a, at, "zone", "name", "x0", "y0", "x1", "y1") && required(a, at, "zone", "name")
                        && unique(a.get("name"), at)) {
                    zones.add(region(a.get("name"), a, at));
                }
            }
            case "checkpoint" -> {
                if (known(a, at, "checkpoint", "name", "x0", "y0", "x1", "y1")) {
                    checkpoints.add(region(a.getOrDefault("name", "checkpoint " + (checkpoints.size() + 1)), a, at));
                }
            }
            default -> other(e);
        }
    }

    /** A solid, a movable object, a score element, or an unknown element. */
    private void other(FlatXmlFile.Element e) {
        Movables.Kind movable = Movables.Kind.of(e.name());
        if (SOLIDS.contains(e.name())) {
            scenery.solid(e.name(), e.attributes(), e.at());
        } else if (movable != null) {
            scenery.movable(movable, e.attributes(), e.at());
        } else if (SCORES.contains(e.name())) {
            scoreElements.add(Map.entry(e, e.name()));
        } else {
            List<String> tags = ELEMENTS.stream().map(n -> "<" + n + ">").toList();
            error(e.at(), Msg.WORLD_UNKNOWN_ELEMENT, e.name(), String.join(", ", tags.subList(0, tags.size() - 1)),
                    tags.get(tags.size() - 1));
        }
    }

    private static List<String> elements() {
        List<String> all = new ArrayList<>(List.of("start", "arena"));
        all.addAll(SOLIDS);
        for (Movables.Kind k : Movables.Kind.values()) {
            all.add(k.xml());
        }
        all.addAll(List.of("zone", "checkpoint"));
        all.addAll(SCORES);
        return List.copyOf(all);
    }

    private void start(Map<String, String> a, SourcePos at) {
        if (start != null) {
            error(at, Msg.ELEMENT_GIVEN_TWICE, "start");
            return;
        }
        if (known(a, at, "start", "x", "y", "z", "yaw", "pitch")) {
            start = new World.Start(coord(a, "x", 0, at), coord(a, "y", 0, at), num(a, "z", 0, at, 0, FAR),
                    num(a, "yaw", 0, at, -360, 360), num(a, "pitch", 0, at, -90, 90));
        }
    }

    /** A rectangle from x0, y0, x1, y1 (all required, x0 < x1, y0 < y1). */
    World.Region region(String name, Map<String, String> a, SourcePos at) {
        String element = name.equals("arena") ? "arena" : "zone";
        required(a, at, element, "x0", "y0", "x1", "y1");
        double x0 = coord(a, "x0", 0, at);
        double y0 = coord(a, "y0", 0, at);
        double x1 = coord(a, "x1", 0, at);
        double y1 = coord(a, "y1", 0, at);
        if (a.containsKey("x1") && a.containsKey("y1") && (!(x0 < x1) || !(y0 < y1))) {
            error(at, Msg.BAD_REGION, a.get("x0"), a.get("x1"), a.get("y0"), a.get("y1"));
        }
        return new World.Region(name, x0, y0, x1, y1, at);
    }

    /** Whether {@code name} is not yet the name of a zone or object (else an error). */
    boolean unique(String name, SourcePos at) {
        if (!names.add(name)) {
            error(at, Msg.NAME_USED_TWICE, name);
            return false;
        }
        return true;
    }

    boolean known(Map<String, String> a, SourcePos at, String element, String... allowed) {
        return xml.known(a, Set.of(allowed), element, at);
    }

    boolean required(Map<String, String> a, SourcePos at, String element, String... keys) {
        return xml.required(a, at, element, keys);
    }

    /** A coordinate within ±{@value #FAR} m. */
    double coord(Map<String, String> a, String key, double fallback, SourcePos at) {
        return num(a, key, fallback, at, -FAR, FAR);
    }

    /** A length, {@value #SMALL}…{@value #FAR} m. */
    double length(Map<String, String> a, String key, double fallback, SourcePos at) {
        return atLeast(a, key, fallback, at, SMALL, FAR, "m (1 mm)");
    }

    /** A mass, {@value #LIGHT}…{@value #HEAVY} kg. */
    double mass(Map<String, String> a, double fallback, SourcePos at) {
        return atLeast(a, "mass", fallback, at, LIGHT, HEAVY, "kg (1 g)");
    }

    /**
     * A number in {@code 0…hi} that must be at least {@code lo} ({@code unit} says it in words),
     * each bound its own message, since {@code 0.001} has no short form in the shared range
     * message; {@code fallback} after an error.
     */
    private double atLeast(Map<String, String> a, String key, double fallback, SourcePos at, double lo, double hi,
                           String unit) {
        int before = xml.errors();
        double v = num(a, key, fallback, at, 0, hi);
        if (xml.errors() == before && a.containsKey(key) && v < lo) {
            error(at, Msg.AT_LEAST, key, Numbers.format(lo), unit, a.get(key));
            return fallback;
        }
        return v;
    }

    /** The attribute {@code friction}, 0…10; the floor's when not given. */
    double friction(Map<String, String> a, SourcePos at) {
        return num(a, "friction", floorFriction, at, 0, 10);
    }

    double floorFriction() {
        return floorFriction;
    }

    double num(Map<String, String> a, String key, double fallback, SourcePos at, double lo, double hi) {
        return xml.number(a, key, fallback, at, false, lo, hi);
    }

    long whole(Map<String, String> a, String key, long fallback, SourcePos at, long lo, long hi) {
        return (long) xml.number(a, key, fallback, at, true, lo, hi);
    }

    void error(SourcePos at, Msg key, Object... args) {
        xml.error(at, key, args);
    }

    /** A box with half extents {@code hx, hy, hz}. */
    static BodyShape.Box box(double hx, double hy, double hz) {
        return new BodyShape.Box(hx, hy, hz);
    }

    /** Rotation by {@code yawDeg} about z. */
    static Mat3 yaw(double yawDeg) {
        return Geo.clean(Geo.rollPitchYaw(0, 0, yawDeg));
    }

    static Vec3 v(double x, double y, double z) {
        return new Vec3(x, y, z);
    }
}
