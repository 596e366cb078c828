package org.parpe.sim.config;

import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import java.nio.file.Path;
import java.util.Collections;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Names;
import org.parpe.core.xml.FlatXmlFile;

/**
 * The parts a class owns: how many of each {@link PartType} (segments, nodes, feet, hubs), so
 * that a robot built on screen can be built on the table. A type the kit does not name is one
 * the class does not have. Read from a kit file (format in {@code docs/simulator.md}):
 *
 * <pre>{@code
 * <kit>
 *   <part type="segment" count="12"/>
 *   <part type="foot" count="4"/>
 * </kit>
 * }</pre>
 *
 * {@link #check} reports, at the first part beyond it, every type a configuration uses more of
 * than the kit has; {@link #left} says what a configuration leaves over (for a builder to show).
 *
 * @param name  a name for messages (the kit file)
 * @param owned how many of each type the class owns (types not in the map: none)
 * @param where where each count is given, for messages (may be {@link SourcePos#NONE})
 */
public record Kit(String name, Map<PartType, Integer> owned, Map<PartType, SourcePos> where) {
    private static final Set<String> PART_ATTRS = Set.of("type", "count");
    /** More parts than any class owns; a count beyond it is a typing mistake. */
    private static final int MAX_COUNT = 100_000;

    public Kit {
        owned = Collections.unmodifiableMap(copy(owned));
        where = Collections.unmodifiableMap(copy(where));
    }

    private static <V> Map<PartType, V> copy(Map<PartType, V> m) {
        Map<PartType, V> out = new EnumMap<>(PartType.class);
        out.putAll(m);
        return out;
    }

    /** A kit made in code (a challenge's rule, a test): {@code owned} parts of each type. */
    public static Kit of(String name, Map<PartType, Integer> owned) {
        return new Kit(name, owned, Map.of());
    }

    /** How many parts of {@code type} the kit has. */
    public int owned(PartType type) {
        return owned.getOrDefault(type, 0);
    }

    /** Parts of each type that {@code config} leaves in the box (negative: parts the kit lacks). */
    public Map<PartType, Integer> left(RobotConfig config) {
        Map<PartType, Integer> left = new EnumMap<>(PartType.class);
        for (PartType t : PartType.values()) {
            left.put(t, owned(t));
        }
        for (PartSpec p : config.parts()) {
            left.merge(p.type(), -1, Integer::sum);
        }
        return left;
    }

    /**
     * Reports each part type {@code config} uses more of than the kit has, at the first part
     * beyond the kit; returns whether the robot fits the kit.
     */
    public boolean check(RobotConfig config, DiagnosticSink diags) {
        Map<PartType, Integer> used = new EnumMap<>(PartType.class);
        Map<PartType, Integer> total = new EnumMap<>(PartType.class);
        config.parts().forEach(p -> total.merge(p.type(), 1, Integer::sum));
        boolean fits = true;
        for (PartSpec p : config.parts()) {
            int n = used.merge(p.type(), 1, Integer::sum);
            if (n == owned(p.type()) + 1) {
                SourcePos at = where.getOrDefault(p.type(), SourcePos.NONE);
                diags.error(p.pos(), Msg.BEYOND_THE_KIT, p.type().noun(), p.name(), p.type().count(total.get(p.type())), name,
                        owned(p.type()), at.line() > 0 ? Message.of(Msg.LINE_NOTE, at.line()) : Message.EMPTY);
                fits = false;
            }
        }
        return fits;
    }

    /** Reads kit file {@code path}; returns {@code null} after reporting errors to {@code diags}. */
    public static Kit read(Path path, DiagnosticSink diags) {
        FlatXmlFile xml = FlatXmlFile.read(path, Message.of(Msg.FILE_KIT), "kit", Message.of(Msg.EXPECTED_KIT), diags);
        if (xml.root() == null) {
            return null;
        }
        for (String a : xml.rootAttributes().keySet()) {
            xml.error(xml.root(), Msg.KIT_UNEXPECTED_ATTRIBUTE, a);
        }
        Map<PartType, Integer> owned = new EnumMap<>(PartType.class);
        Map<PartType, SourcePos> where = new EnumMap<>(PartType.class);
        List<String> types = java.util.Arrays.stream(PartType.values()).map(PartType::xmlName).toList();
        for (FlatXmlFile.Element e : xml.children()) {
            Map<String, String> a = e.attributes();
            if (!e.name().equals("part")) {
                xml.error(e.at(), Msg.KIT_UNKNOWN_ELEMENT, e.name());
                continue;
            }
            if (!xml.known(a, PART_ATTRS, "part", e.at()) || !xml.required(a, e.at(), "part", "type", "count")) {
                continue;
            }
            PartType t = PartType.ofXmlName(a.get("type"));
            if (t == null) {
                xml.error(e.at(), Msg.KIT_UNKNOWN_PART_TYPE, a.get("type"), String.join(", ", types),
                        Names.suggest(a.get("type"), types));
                continue;
            }
            int count = (int) xml.number(a, "count", 0, e.at(), true, 0, MAX_COUNT);
            if (where.containsKey(t)) {
                xml.error(e.at(), Msg.KIT_TWICE, t.xmlName(), where.get(t).line());
                continue;
            }
            owned.put(t, count);
            where.put(t, e.at());
        }
        if (!xml.ok()) {
            return null;
        }
        if (owned.isEmpty()) {
            xml.error(xml.root(), Msg.KIT_EMPTY);
            return null;
        }
        return new Kit(path.toString(), owned, where);
    }
}
