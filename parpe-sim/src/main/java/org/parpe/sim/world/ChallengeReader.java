package org.parpe.sim.world;

import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.xml.FlatXmlFile;
import org.parpe.sim.config.Kit;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;

/**
 * Reads a challenge file with the project's flat XML reader, as world files and robot
 * configurations are read: the same input limits and {@code FILE:LINE:COL} messages. Reports
 * every problem it finds, then returns {@code null}. The world file is only named here; the
 * caller reads it with {@link WorldReader}.
 */
public final class ChallengeReader {
    /** The most modules a challenge may allow: the size limit of robot configurations. */
    public static final int MAX_MODULES = 1000;
    private static final Set<String> ROOT = Set.of("world", "robot", "duration", "tick", "max-modules", "sensors",
            "kit", "tie-break");

    private ChallengeReader() {
    }

    /** Reads {@code path}; returns {@code null} after reporting errors to {@code diags}. */
    public static Challenge read(Path path, DiagnosticSink diags) {
        FlatXmlFile xml = FlatXmlFile.read(path, Message.of(Msg.FILE_CHALLENGE), "challenge",
                Message.of(Msg.EXPECTED_CHALLENGE), diags);
        if (xml.root() == null) {
            return null;
        }
        Map<String, String> a = xml.rootAttributes();
        xml.known(a, ROOT, "challenge", xml.root());
        xml.required(a, xml.root(), "challenge", "world", "robot");
        double duration = xml.number(a, "duration", 60, xml.root(), false, 0.01, 3600);
        double tick = xml.number(a, "tick", 0.01, xml.root(), false, 0.001, 1);
        int maxModules = (int) xml.number(a, "max-modules", 32, xml.root(), true, 1, MAX_MODULES);
        Set<String> sensors = sensors(xml, a.get("sensors"), xml.root());
        Challenge.TieBreak tie = tieBreak(xml, a.getOrDefault("tie-break", "distance"), xml.root());
        Map<String, Double> parameters = new TreeMap<>();
        for (FlatXmlFile.Element e : xml.children()) {
            parameter(xml, e, parameters);
        }
        if (!xml.ok()) {
            return null;
        }
        Path parent = path.toAbsolutePath().getParent();
        Path world = parent.resolve(a.get("world").trim()).normalize();
        if (a.containsKey("kit") && !fitsKit(parent, a, xml.root(), diags)) {
            return null;
        }
        return new Challenge(path, world, a.get("robot").trim(), duration, tick, parameters, maxModules, sensors, tie);
    }

    /**
     * The kit rule: the challenge's robot must be one the class can build from its kit (the
     * kit file, named relative to the challenge). A problem on a generated robot, which has no
     * file of its own, is reported at the challenge's element.
     */
    private static boolean fitsKit(Path folder, Map<String, String> a, SourcePos at, DiagnosticSink diags) {
        Kit kit = Kit.read(folder.resolve(a.get("kit").trim()).normalize(), diags);
        if (kit == null) {
            return false;
        }
        String robot = a.get("robot").trim();
        String spec = RobotConfigs.isFile(robot) ? folder.resolve(robot).normalize().toString() : robot;
        DiagnosticList found = new DiagnosticList();
        RobotConfig config = RobotConfigs.resolve(spec, new int[0], found);
        if (config != null) {
            kit.check(config, found);
        }
        for (Diagnostic d : found.all()) {
            diags.report(d.pos().line() > 0 ? d : new Diagnostic(d.severity(), at, Msg.KIT_RULE, robot, d.text()));
        }
        return config != null && !found.hasErrors();
    }

    private static void parameter(FlatXmlFile xml, FlatXmlFile.Element e, Map<String, Double> into) {
        if (!e.name().equals("parameter")) {
            xml.error(e.at(), Msg.CHALLENGE_UNKNOWN_ELEMENT, e.name());
            return;
        }
        Map<String, String> a = e.attributes();
        if (!xml.known(a, Set.of("name", "value"), "parameter", e.at())
                || !xml.required(a, e.at(), "parameter", "name", "value")) {
            return;
        }
        double v = xml.number(a, "value", Double.NaN, e.at(), false, -1e9, 1e9);
        if (into.put(a.get("name"), v) != null) {
            xml.error(e.at(), Msg.PARAMETER_SET_TWICE, a.get("name"));
        }
    }

    /** The sensor types of {@code v} (comma-separated; "" allows none); all of them without the attribute. */
    private static Set<String> sensors(FlatXmlFile xml, String v, SourcePos at) {
        if (v == null) {
            return Set.copyOf(Vocabulary.SENSOR_TYPES);
        }
        Set<String> out = new TreeSet<>();
        for (String t : v.split(",")) {
            String type = t.trim();
            if (type.isEmpty()) {
                continue;
            }
            if (!Vocabulary.SENSOR_TYPES.contains(type)) {
                xml.error(at, Msg.SENSORS_LIST, String.join(", ", Vocabulary.SENSOR_TYPES), type);
            }
            out.add(type);
        }
        return out;
    }

    private static Challenge.TieBreak tieBreak(FlatXmlFile xml, String v, SourcePos at) {
        for (Challenge.TieBreak t : Challenge.TieBreak.values()) {
            if (t.name().toLowerCase(Locale.ROOT).equals(v)) {
                return t;
            }
        }
        xml.error(at, Msg.BAD_TIE_BREAK, v);
        return Challenge.TieBreak.DISTANCE;
    }
}
