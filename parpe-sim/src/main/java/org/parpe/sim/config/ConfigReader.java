package org.parpe.sim.config;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import org.parpe.core.xml.FlatXmlFile;

/**
 * Reads a robot configuration file (format in {@code docs/simulator.md}) through
 * {@link FlatXmlFile}, keeping the place of every element for messages. Reports every problem
 * it finds; the result is checked further when the robot is assembled.
 */
final class ConfigReader {
    private static final Set<String> PART_ATTRS = Set.of("name", "type", "id", "angle", "plates", "limp");
    private static final Set<String> CONNECT_ATTRS = Set.of("from", "to", "orientation");
    private static final Set<String> ROOT_ATTRS = Set.of("part", "x", "y", "roll", "pitch", "yaw", "height");

    private static final Message WHAT = Message.of(Msg.FILE_ROBOT_CONFIG);
    private static final String ROOT = "robot-config";
    private static final Message EXPECTED = Message.of(Msg.EXPECTED_ROBOT_CONFIG);

    private final FlatXmlFile xml;
    private final List<PartSpec> parts = new ArrayList<>();
    private final List<Connection> connections = new ArrayList<>();
    private final List<RootPose> roots = new ArrayList<>();

    private ConfigReader(FlatXmlFile xml) {
        this.xml = xml;
    }

    /** Reads {@code path}; returns {@code null} after reporting errors. */
    static RobotConfig read(Path path, DiagnosticSink diags) {
        return read(FlatXmlFile.read(path, WHAT, ROOT, EXPECTED, diags), path.toString(), false).config();
    }

    /**
     * Reads {@code text}, the contents of {@code file}, as {@link #read(Path, DiagnosticSink)}
     * reads a file; every element's place carries its span. A configuration without parts is
     * no error here (a file being built starts so); its configuration is null.
     */
    static ConfigFile read(String file, String text, DiagnosticSink diags) {
        return read(FlatXmlFile.read(file, text, WHAT, ROOT, EXPECTED, diags), file, true);
    }

    private static ConfigFile read(FlatXmlFile xml, String name, boolean emptyAllowed) {
        if (xml.root() == null) {
            return new ConfigFile(null, null, List.of());
        }
        ConfigReader r = new ConfigReader(xml);
        for (String attr : xml.rootAttributes().keySet()) {
            xml.error(xml.root(), Msg.CONFIG_UNEXPECTED_ATTRIBUTE, attr);
        }
        for (FlatXmlFile.Element e : xml.children()) {
            switch (e.name()) {
                case "part" -> r.part(e.attributes(), e.at());
                case "connect" -> r.connect(e.attributes(), e.at());
                case "root" -> r.root(e.attributes(), e.at());
                default -> xml.error(e.at(), Msg.CONFIG_UNKNOWN_ELEMENT, e.name());
            }
        }
        if (!xml.ok()) {
            return new ConfigFile(null, xml.root(), xml.children());
        }
        if (r.roots.isEmpty() && !r.parts.isEmpty()) {
            r.roots.add(new RootPose(r.parts.get(0).name(), 0, 0, 0, 0, 0));
        }
        if (r.parts.isEmpty()) {
            if (!emptyAllowed) {
                xml.error(xml.start(), Msg.CONFIG_NO_PART);
            }
            return new ConfigFile(null, xml.root(), xml.children());
        }
        return new ConfigFile(new RobotConfig(name, r.parts, r.connections, r.roots), xml.root(), xml.children());
    }

    private void part(Map<String, String> a, SourcePos at) {
        if (!known(a, PART_ATTRS, "part", at) || !required(a, at, "part", "name", "type")) {
            return;
        }
        PartType type = PartType.ofXmlName(a.get("type"));
        if (type == null) {
            error(at, Msg.UNKNOWN_PART_TYPE, a.get("type"));
            return;
        }
        if (type == PartType.SEGMENT && !a.containsKey("id")) {
            error(at, Msg.SEGMENT_NEEDS_ID);
            return;
        }
        if (type != PartType.SEGMENT && (a.containsKey("id") || a.containsKey("angle") || a.containsKey("limp"))) {
            error(at, Msg.ONLY_SEGMENTS_TAKE, a.get("name"), type.xmlName());
        }
        if (type != PartType.HUB && a.containsKey("plates")) {
            error(at, Msg.ONLY_HUBS_TAKE_PLATES, a.get("name"), type.xmlName());
        }
        int id = type == PartType.SEGMENT ? (int) number(a, "id", 0, at, true) : -1;
        double angle = number(a, "angle", 0, at, false);
        int plates = (int) number(a, "plates", type.defaultPlates(), at, true);
        String limp = a.getOrDefault("limp", "false");
        if (!limp.equals("true") && !limp.equals("false")) {
            error(at, Msg.LIMP_TRUE_OR_FALSE, limp);
        }
        parts.add(new PartSpec(a.get("name"), type, id, angle, plates, limp.equals("true"), at));
    }

    private void connect(Map<String, String> a, SourcePos at) {
        if (!known(a, CONNECT_ATTRS, "connect", at) || !required(a, at, "connect", "from", "to")) {
            return;
        }
        String[] from = plateRef(a.get("from"), at);
        String[] to = plateRef(a.get("to"), at);
        double deg = number(a, "orientation", 0, at, false);
        if (deg % 90 != 0 || deg < 0 || deg >= 360) {
            error(at, Msg.BAD_ORIENTATION, a.get("orientation"));
            return;
        }
        if (from != null && to != null) {
            connections.add(new Connection(from[0], Integer.parseInt(from[1]), to[0], Integer.parseInt(to[1]),
                    (int) (deg / 90), at));
        }
    }

    /** {@code "name.plate"} split in two, or {@code null} after an error. */
    private String[] plateRef(String ref, SourcePos at) {
        int dot = ref.lastIndexOf('.');
        String plate = ref.substring(dot + 1);
        if (dot <= 0 || plate.isEmpty() || plate.length() > 2 || !plate.chars().allMatch(c -> c >= '0' && c <= '9')) {
            error(at, Msg.BAD_PLATE_REF, ref);
            return null;
        }
        return new String[] {ref.substring(0, dot), ref.substring(dot + 1)};
    }

    private void root(Map<String, String> a, SourcePos at) {
        if (!known(a, ROOT_ATTRS, "root", at) || !required(a, at, "root", "part")) {
            return;
        }
        if (roots.stream().anyMatch(r -> r.part().equals(a.get("part")))) {
            error(at, Msg.ALREADY_A_ROOT, a.get("part"));
            return;
        }
        RootPose root = new RootPose(a.get("part"), number(a, "x", 0, at, false), number(a, "y", 0, at, false),
                number(a, "roll", 0, at, false), number(a, "pitch", 0, at, false), number(a, "yaw", 0, at, false),
                number(a, "height", RootPose.RESTING, at, false), at);
        if (root.height() < 0) {
            error(at, Msg.HEIGHT_NEGATIVE, root.height());
        }
        roots.add(root);
    }

    private boolean known(Map<String, String> a, Set<String> allowed, String element, SourcePos at) {
        return xml.known(a, allowed, element, at);
    }

    private boolean required(Map<String, String> a, SourcePos at, String element, String... keys) {
        return xml.required(a, at, element, keys);
    }

    private double number(Map<String, String> a, String key, double fallback, SourcePos at, boolean whole) {
        return xml.number(a, key, fallback, at, whole, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
    }

    private void error(SourcePos at, Msg key, Object... args) {
        xml.error(at, key, args);
    }
}
