package org.parpe.sim.build;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.xml.FlatXmlFile;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.config.ConfigFile;
import org.parpe.sim.config.Connection;
import org.parpe.sim.config.Kit;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.PartType;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;
import org.parpe.sim.internal.Assembly;
import org.parpe.sim.text.SimMsg;

/**
 * One state of a robot configuration being built: its text and what it reads as. Immutable, so
 * a builder may make it on a worker thread and hand it to the UI thread.
 *
 * <p>The text is the source: a draft is read from it by the reader of configuration files
 * ({@link RobotConfigs#read}) and assembled as the simulator assembles it, and every edit
 * ({@link #add}, {@link #remove}, {@link #turn}, …) is a {@link BuildEdit} on the text made
 * through the edit layer ({@code org.parpe.core.edit}): only what changes changes, comments,
 * order and quoting stay. {@link #apply} gives the draft after an edit, so a preview is
 * {@code draft.apply(edit).bodies()}.
 */
public final class RobotDraft {
    private static final String EMPTY = "<?xml version=\"1.0\" ?>\n<robot-config>\n</robot-config>\n";

    private final String file;
    private final String text;
    private final ConfigFile read;
    private final List<Diagnostic> problems;
    private final DraftTree tree;
    private final List<SimBody> bodies;
    /** Every plate by "part.plate", in configuration order, with whether a connection uses it. */
    private final Map<String, Plate> plates;

    /** A plate where it is, and whether a connection uses it. */
    record Plate(BuildPlate where, boolean used) {
    }

    private RobotDraft(String file, String text) {
        this.file = file;
        this.text = text;
        DiagnosticList diags = new DiagnosticList();
        ConfigFile r = new ConfigFile(null, null, List.of());
        Assembly assembly = null;
        try {
            r = RobotConfigs.read(file, text, diags);
            assembly = r.config() == null ? null : Assembly.build(r.config(), diags);
        } catch (RuntimeException e) {
            // never lose the builder to a reader's or assembler's bug: say so where the file starts
            diags.error(new SourcePos(file, 1, 1), SimMsg.DRAFT_INTERNAL_ERROR, e);
        }
        this.read = r;
        this.problems = List.copyOf(diags.all());
        this.tree = r.config() == null ? null : new DraftTree(r.config());
        this.bodies = assembly == null ? List.of() : bodies(assembly);
        this.plates = assembly == null ? Map.of() : plates(r.config(), assembly);
    }

    /** The draft of {@code text}, the contents of {@code file} (the name in messages). Never throws: problems are located. */
    public static RobotDraft of(String file, String text) {
        return new RobotDraft(file, text);
    }

    /** A configuration with no part yet, an XML declaration as the examples have. */
    public static RobotDraft empty(String file) {
        return of(file, EMPTY);
    }

    /**
     * "Make editable": the configuration a generator makes ({@code snake:n=12}, {@code wheel},
     * …) written out as text that reads to the same robot (the same parts in the same order,
     * the same connections and root poses).
     *
     * @throws IllegalArgumentException with the located messages when {@code spec} is not a generator's
     */
    public static RobotDraft fromGenerator(String file, String spec) {
        return fromGenerator(file, spec, new int[0]);
    }

    /**
     * "Make editable" for a script: the robot a run of a script with modules {@code moduleIds}
     * simulates for {@code spec} (a generator sized by the script's modules, as
     * {@link RobotConfigs#resolve} sizes it), written out as text.
     *
     * @throws IllegalArgumentException with the located messages when {@code spec} is not a generator's
     */
    public static RobotDraft fromGenerator(String file, String spec, int[] moduleIds) {
        DiagnosticList diags = new DiagnosticList();
        if (RobotConfigs.isFile(spec)) {
            throw new IllegalArgumentException("'" + spec + "' is a configuration file, not a generator; open it");
        }
        RobotConfig c = RobotConfigs.resolve(spec, moduleIds, diags);
        if (c == null) {
            throw new IllegalArgumentException(String.join("\n", diags.all().stream().map(Diagnostic::format).toList()));
        }
        return of(file, ConfigText.of(c, spec));
    }

    /** The file name used in messages. */
    public String file() {
        return file;
    }

    /** The configuration's text. */
    public String text() {
        return text;
    }

    /** What the text reads as, or null when it has errors (or no part yet). */
    public RobotConfig config() {
        return read.config();
    }

    /**
     * Every problem of the reader and of the assembly (overlapping parts, a plate used twice, a
     * loop that does not close, an unknown part type, binary text, a DOCTYPE), each at
     * {@code FILE:LINE:COL}; a configuration without parts yet has none.
     */
    public List<Diagnostic> problems() {
        return problems;
    }

    /**
     * The robot assembled at rest, its lowest point on the floor as the simulator places it at
     * the start (one body per rigid piece, {@link SimBody#part} the part's name); empty when the
     * configuration has errors.
     */
    public List<SimBody> bodies() {
        return bodies;
    }

    /** Every plate no connection uses, part by part in file order, where it is at rest; empty when the robot does not assemble. */
    public List<BuildPlate> freePlates() {
        return plates.values().stream().filter(p -> !p.used()).map(Plate::where).toList();
    }

    /** The names of the parts in file order (empty when the configuration has errors). */
    public List<String> partNames() {
        return config() == null ? List.of() : config().parts().stream().map(PartSpec::name).toList();
    }

    /** The part called {@code name}. */
    public Optional<PartSpec> part(String name) {
        return config() == null ? Optional.empty() : config().part(name);
    }

    /** The name of the root part (the first root's, when the file holds several robots), or null. */
    public String root() {
        return config() == null ? null : config().root().part();
    }

    /**
     * The plate of the part {@code part} hangs on (the parent's plate its connection names),
     * where it is at rest; empty for a root, an unknown part or a robot that does not assemble.
     */
    public Optional<BuildPlate> attachment(String part) {
        int i = tree == null ? -1 : tree.index(part);
        Connection c = i < 0 ? null : tree.parent(i);
        if (c == null) {
            return Optional.empty();
        }
        String parent = config().parts().get(tree.parentPart(i)).name();
        Plate p = plates.get(c.from().equals(parent) ? c.from() + "." + c.fromPlate() : c.to() + "." + c.toPlate());
        return p == null ? Optional.empty() : Optional.of(p.where());
    }

    /**
     * The part a problem (or any place in the text) is about, for a builder to mark: the part
     * whose {@code <part>} element holds {@code pos}, the part a {@code <connect>} holding it
     * attaches (its {@code to} side) or a {@code <root>} names; empty elsewhere.
     */
    public Optional<String> partAt(SourcePos pos) {
        for (FlatXmlFile.Element e : read.elements()) {
            SourceSpan s = e.at().span();
            boolean holds = pos.offset() >= 0 && s != null ? s.start() <= pos.offset() && pos.offset() < s.end()
                    : e.at().equals(pos);
            String ref = switch (e.name()) {
                case "part" -> e.attributes().get("name");
                case "connect" -> e.attributes().get("to");
                case "root" -> e.attributes().get("part");
                default -> null;
            };
            if (holds && ref != null) {
                int dot = e.name().equals("connect") ? ref.lastIndexOf('.') : -1;
                return Optional.of(dot > 0 ? ref.substring(0, dot) : ref);
            }
        }
        return Optional.empty();
    }

    /** The parts of each type the robot leaves in {@code kit} (negative: parts the kit lacks); the whole kit before the first part. */
    public Map<PartType, Integer> left(Kit kit) {
        if (config() != null) {
            return kit.left(config());
        }
        Map<PartType, Integer> all = new java.util.EnumMap<>(PartType.class);
        for (PartType t : PartType.values()) {
            all.put(t, kit.owned(t));
        }
        return all;
    }

    /** The draft after {@code e}, read again from the edited text. */
    public RobotDraft apply(BuildEdit e) {
        if (e.refused()) {
            throw new IllegalArgumentException("a refused edit cannot be applied: " + e.refusal());
        }
        return of(file, e.edit().apply(text));
    }

    // --- edits (made by DraftEdits) ---

    /** The first part of a configuration without parts; it becomes the root. {@code hubPlates} counts only for a hub. */
    public BuildEdit first(PartType type, int hubPlates) {
        return new DraftEdits(this).first(type, hubPlates);
    }

    /**
     * A new part of {@code type} bolted with its plate {@code newPlate} onto free plate
     * {@code plate} of {@code part}, turned {@code quarterTurns} × 90° ({@code hubPlates} counts
     * only for a hub). It gets the first free name of its type ({@code s0, s1…}, {@code node0…},
     * {@code foot0…}, {@code hub0…}) and, a segment, the lowest module ID no segment has.
     * Refused when a part or plate does not exist or is taken, or when {@code kitOrNull} has
     * no part of the type left.
     */
    public BuildEdit add(String part, int plate, PartType type, int newPlate, int quarterTurns, int hubPlates,
                         Kit kitOrNull) {
        return new DraftEdits(this).add(part, plate, type, newPlate, quarterTurns, hubPlates, kitOrNull);
    }

    /**
     * Removes {@code part} with every part that hangs on it away from the root (what the robot
     * no longer holds without it; in a loop, what the other way round still holds stays), and
     * every connection of those parts. The root is removed only when nothing hangs on it (then the
     * file has no part); else refused: make another part the root first.
     */
    public BuildEdit remove(String part) {
        return new DraftEdits(this).remove(part);
    }

    /** Turns {@code part} on the plate it hangs on: the orientation of that connection (0 leaves the attribute out). */
    public BuildEdit turn(String part, int quarterTurns) {
        return new DraftEdits(this).turn(part, quarterTurns);
    }

    /** Gives segment {@code part} module ID {@code id}; refused when another segment has it. */
    public BuildEdit setModuleId(String part, int id) {
        return new DraftEdits(this).setModuleId(part, id);
    }

    /** Sets segment {@code part}'s initial joint angle, −90 to 90 degrees (0 leaves the attribute out). */
    public BuildEdit setAngle(String part, double degrees) {
        return new DraftEdits(this).setAngle(part, degrees);
    }

    /** Makes segment {@code part} start limp or not (not limp leaves the attribute out). */
    public BuildEdit setLimp(String part, boolean limp) {
        return new DraftEdits(this).setLimp(part, limp);
    }

    /**
     * Makes {@code part} the root of its robot: the {@code <root>} element's {@code part} is
     * rewritten (its pose attributes stay), or a {@code <root>} is added as the last element.
     */
    public BuildEdit makeRoot(String part) {
        return new DraftEdits(this).makeRoot(part);
    }

    /**
     * Sets one attribute of the (first) robot's root pose: {@code x}, {@code y} (m),
     * {@code roll}, {@code pitch}, {@code yaw} (degrees) or {@code height} (m); its default
     * (0, or {@link org.parpe.sim.config.RootPose#RESTING} for the height) leaves it out. A
     * {@code <root>} is added when the file has none.
     */
    public BuildEdit setRootPose(String attribute, double value) {
        return new DraftEdits(this).setRootPose(attribute, value);
    }

    /**
     * Connects two free plates that meet, closing a loop: a {@code <connect>} with the
     * orientation that lines them up, when they meet within the simulator's tolerance; else
     * refused saying how far apart they are (distance and angle).
     */
    public BuildEdit closeLoop(String a, int plateA, String b, int plateB) {
        return new DraftEdits(this).closeLoop(a, plateA, b, plateB);
    }

    /** The distance between the centres of two plates at rest, metres; NaN when either is unknown. */
    public double gap(String a, int plateA, String b, int plateB) {
        Plate pa = plates.get(a + "." + plateA);
        Plate pb = plates.get(b + "." + plateB);
        return pa == null || pb == null ? Double.NaN : Geo.sub(pa.where().centre(), pb.where().centre()).length();
    }

    /** Gives every segment a module ID in chain order from the root, 0, 1, 2…, as one edit. */
    public BuildEdit assignIds() {
        return new DraftEdits(this).assignIds();
    }

    // --- what the edits read ---

    ConfigFile read() {
        return read;
    }

    DraftTree tree() {
        return tree;
    }

    /** The plate {@code part.plate}, or null (unknown, or the robot does not assemble). */
    Plate plate(String part, int plate) {
        return plates.get(part + "." + plate);
    }

    private static List<SimBody> bodies(Assembly a) {
        List<SimBody> out = new ArrayList<>(a.pieces().size());
        for (Assembly.PlacedPiece p : a.pieces()) {
            out.add(new SimBody(p.part().moduleId(), p.part().name(), p.def().kind(), p.def().shape(), p.position(),
                    p.rotation()));
        }
        return Collections.unmodifiableList(out);
    }

    private static Map<String, Plate> plates(RobotConfig c, Assembly a) {
        Map<String, Plate> out = new LinkedHashMap<>();
        for (Assembly.PlateSite s : a.plates()) {
            Assembly.PlacedPiece piece = a.pieces().get(s.piece());
            String name = c.parts().get(s.part()).name();
            BuildPlate where = new BuildPlate(name, s.plate(),
                    Geo.add(piece.position(), Geo.mul(piece.rotation(), s.centre())),
                    Geo.mul(piece.rotation(), s.normal()), Geo.mul(piece.rotation(), s.up()));
            out.put(where.ref(), new Plate(where, s.connected()));
        }
        return Collections.unmodifiableMap(out);
    }
}
