package org.parpe.sim.config;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.dataformat.xml.XmlFactory;
import com.fasterxml.jackson.dataformat.xml.deser.FromXmlParser;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.model.Numbers;
import org.parpe.core.xml.InputFiles;

/**
 * Reads a robot configuration file (format in {@code docs/simulator.md}) with Jackson's XML
 * streaming parser, keeping the place of every element for messages. Reports every problem
 * it finds; the result is checked further when the robot is assembled.
 */
final class ConfigReader {
    private static final Set<String> PART_ATTRS = Set.of("name", "type", "id", "angle", "plates", "limp");
    private static final Set<String> CONNECT_ATTRS = Set.of("from", "to", "orientation");
    private static final Set<String> ROOT_ATTRS = Set.of("part", "x", "y", "roll", "pitch", "yaw", "height");

    private final String file;
    private final DiagnosticSink diags;
    private final List<PartSpec> parts = new ArrayList<>();
    private final List<Connection> connections = new ArrayList<>();
    private RootPose root;
    private boolean ok = true;

    private ConfigReader(String file, DiagnosticSink diags) {
        this.file = file;
        this.diags = diags;
    }

    /** Reads {@code path}; returns {@code null} after reporting errors. */
    static RobotConfig read(Path path, DiagnosticSink diags) {
        ConfigReader r = new ConfigReader(path.toString(), diags);
        try (InputStream in = InputFiles.open(path);
             JsonParser p = new XmlFactory().createParser(in)) {
            r.document(p);
        } catch (JsonProcessingException e) {
            JsonLocation l = e.getLocation();
            r.error(l == null ? new SourcePos(r.file, 1, 1) : r.pos(l), "not well-formed XML: " + e.getOriginalMessage());
        } catch (IOException e) {
            r.error(new SourcePos(r.file, 1, 1), "cannot read the configuration file: " + e.getMessage());
        }
        if (!r.ok) {
            return null;
        }
        if (r.root == null && !r.parts.isEmpty()) {
            r.root = new RootPose(r.parts.get(0).name(), 0, 0, 0, 0, 0);
        }
        if (r.parts.isEmpty()) {
            r.error(new SourcePos(r.file, 1, 1), "the configuration defines no <part>");
            return null;
        }
        return new RobotConfig(path.toString(), r.parts, r.connections, r.root);
    }

    private void document(JsonParser p) throws IOException {
        if (p.nextToken() != JsonToken.START_OBJECT) {
            error(new SourcePos(file, 1, 1), "expected a <robot-config> element with <part> and <connect> elements");
            return;
        }
        String rootName = p instanceof FromXmlParser x ? x.getStaxReader().getLocalName() : "robot-config";
        if (!"robot-config".equals(rootName)) {
            error(pos(p.currentTokenLocation()), "<" + rootName + "> is not a robot configuration"
                    + ("program".equals(rootName) ? " but a PARSL script" : "")
                    + "; expected a <robot-config> element with <part> and <connect> elements, or a generator such as snake");
            return;
        }
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String name = p.currentName();
            SourcePos at = pos(p.currentTokenLocation());
            JsonToken t = p.nextToken();
            if (t != JsonToken.START_OBJECT) {
                error(at, "unexpected '" + name + "' in <robot-config>; expected <part>, <connect> or <root>");
                continue;
            }
            Map<String, String> attrs = attributes(p, name, at);
            switch (name) {
                case "part" -> part(attrs, at);
                case "connect" -> connect(attrs, at);
                case "root" -> root(attrs, at);
                default -> error(at, "unknown element <" + name + ">; expected <part>, <connect> or <root>");
            }
        }
    }

    /** The attributes of the current element; nested elements are errors. */
    private Map<String, String> attributes(JsonParser p, String element, SourcePos at) throws IOException {
        Map<String, String> attrs = new LinkedHashMap<>();
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String key = p.currentName();
            JsonToken t = p.nextToken();
            if (t == JsonToken.START_OBJECT || t == JsonToken.START_ARRAY) {
                error(pos(p.currentTokenLocation()), "<" + element + "> may not contain <" + key + ">");
                p.skipChildren();
            } else if (!key.isEmpty()) {
                attrs.put(key, p.getText().trim());
            } else if (!p.getText().isBlank()) {
                error(at, "<" + element + "> may not contain text");
            }
        }
        return attrs;
    }

    private void part(Map<String, String> a, SourcePos at) {
        if (!known(a, PART_ATTRS, "part", at) || !required(a, at, "part", "name", "type")) {
            return;
        }
        PartType type = PartType.ofXmlName(a.get("type"));
        if (type == null) {
            error(at, "unknown part type '" + a.get("type") + "'; expected segment, node, foot or hub");
            return;
        }
        if (type == PartType.SEGMENT && !a.containsKey("id")) {
            error(at, "a segment needs an id (its logical module ID)");
            return;
        }
        if (type != PartType.SEGMENT && (a.containsKey("id") || a.containsKey("angle") || a.containsKey("limp"))) {
            error(at, "only segments take id, angle and limp; '" + a.get("name") + "' is a " + type.xmlName());
        }
        if (type != PartType.HUB && a.containsKey("plates")) {
            error(at, "only hubs take plates; '" + a.get("name") + "' is a " + type.xmlName());
        }
        int id = type == PartType.SEGMENT ? (int) number(a, "id", 0, at, true) : -1;
        double angle = number(a, "angle", 0, at, false);
        int plates = (int) number(a, "plates", type.defaultPlates(), at, true);
        String limp = a.getOrDefault("limp", "false");
        if (!limp.equals("true") && !limp.equals("false")) {
            error(at, "limp must be true or false, got '" + limp + "'");
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
            error(at, "orientation must be 0, 90, 180 or 270 (degrees), got " + a.get("orientation"));
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
        if (dot <= 0 || !ref.substring(dot + 1).matches("[0-9]{1,2}")) {
            error(at, "expected PART.PLATE such as 's3.1', got '" + ref + "'");
            return null;
        }
        return new String[] {ref.substring(0, dot), ref.substring(dot + 1)};
    }

    private void root(Map<String, String> a, SourcePos at) {
        if (root != null) {
            error(at, "<root> is given twice");
            return;
        }
        if (!known(a, ROOT_ATTRS, "root", at) || !required(a, at, "root", "part")) {
            return;
        }
        root = new RootPose(a.get("part"), number(a, "x", 0, at, false), number(a, "y", 0, at, false),
                number(a, "roll", 0, at, false), number(a, "pitch", 0, at, false), number(a, "yaw", 0, at, false),
                number(a, "height", RootPose.RESTING, at, false));
        if (root.height() < 0) {
            error(at, "height must be >= 0 m, got " + root.height());
        }
    }

    private boolean known(Map<String, String> a, Set<String> allowed, String element, SourcePos at) {
        boolean good = true;
        for (String k : a.keySet()) {
            if (!allowed.contains(k)) {
                error(at, "<" + element + "> has no attribute '" + k + "'; it takes "
                        + String.join(", ", allowed.stream().sorted().toList()));
                good = false;
            }
        }
        return good;
    }

    private boolean required(Map<String, String> a, SourcePos at, String element, String... keys) {
        boolean good = true;
        for (String k : keys) {
            if (!a.containsKey(k) || a.get(k).isEmpty()) {
                error(at, "<" + element + "> needs the attribute '" + k + "'");
                good = false;
            }
        }
        return good;
    }

    private double number(Map<String, String> a, String key, double fallback, SourcePos at, boolean whole) {
        String v = a.get(key);
        if (v == null) {
            return fallback;
        }
        // the plain decimals of scripts: Double.parseDouble would take "1d", "0x1p3" or "NaN"
        Double d = Numbers.parsePlain(v);
        if (d == null || whole && d != Math.rint(d)) {
            error(at, key + " must be " + (whole ? "a whole number" : "a number") + ", got '" + v + "'");
            return fallback;
        }
        return d;
    }

    private SourcePos pos(JsonLocation l) {
        return new SourcePos(file, Math.max(1, l.getLineNr()), Math.max(1, l.getColumnNr()));
    }

    private void error(SourcePos at, String message) {
        diags.error(at, message);
        ok = false;
    }
}
