package org.parpe.core.load;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.ExprCompiler;
import org.parpe.core.expr.Expression;
import org.parpe.core.expr.Names;
import org.parpe.core.expr.Scope;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.lang.Vocabulary.Element;
import org.parpe.core.model.ActuatorDecl;
import org.parpe.core.model.Group;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Robot;
import org.parpe.core.model.SensorDecl;
import org.parpe.core.xml.InputFiles;
import org.parpe.core.xml.SourceText;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XText;
import org.parpe.core.xml.XmlReader;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/** Resolves {@code <robot>} (PARSL.md §2, §13 rule 11): groups, modules and sensors. */
final class RobotResolver {
    /** The largest module ID a script may use. */
    static final int MAX_ID = 65_535;

    private final DiagnosticSink d;
    private final NameRegistry names;
    private final Scope paramScope;
    private final Map<String, Group> groups = new LinkedHashMap<>();
    private final TreeSet<Integer> modules = new TreeSet<>();
    private final List<SensorDecl> sensors = new ArrayList<>();
    private final List<ActuatorDecl> actuators = new ArrayList<>();
    private final java.util.Set<String> broken = new java.util.HashSet<>();
    private Path file;

    /**
     * A resolved robot.
     *
     * @param robot  the robot, or {@code null} if it is absent or could not be resolved
     * @param broken groups defined with errors: uses of them are not reported again
     * @param file   the robot file read for {@code <robot file=...>}, or {@code null}
     */
    record Resolved(Robot robot, java.util.Set<String> broken, Path file) {
        Resolved {
            broken = java.util.Set.copyOf(broken);
        }
    }

    /**
     * A robot file as read from disk, before any parameter value is known: read once per
     * {@link ParsedScript} and given to every resolution of it.
     *
     * @param path        the file
     * @param root        its root element, or {@code null} when it could not be read or parsed
     * @param ioError     why it could not be read, or {@code null}
     * @param diagnostics what parsing it reported
     */
    record FileRead(Path path, XElement root, Message ioError, List<Diagnostic> diagnostics) {
        FileRead {
            diagnostics = List.copyOf(diagnostics);
        }

        /** Reads and parses {@code path}. */
        static FileRead of(Path path) {
            String text;
            try {
                text = InputFiles.readText(path);
            } catch (java.io.IOException e) {
                return new FileRead(path, null, Message.verbatim(String.valueOf(e.getMessage())), List.of());
            }
            DiagnosticList found = new DiagnosticList();
            XElement root = XmlReader.read(new SourceText(path.toString(), text), found);
            return new FileRead(path, root, null, found.all());
        }
    }

    private RobotResolver(DiagnosticSink d, NameRegistry names, Scope paramScope) {
        this.d = d;
        this.names = names;
        this.paramScope = paramScope;
    }

    /**
     * Resolves the robot section {@code robot} of {@code mainFile} (or its file, already read as
     * {@code robotFile}), whose groups' ranges may use the parameters of {@code paramScope};
     * reports a missing one at {@code rootPos}.
     */
    static Resolved resolve(DiagnosticSink d, NameRegistry names, Scope paramScope, XElement robot, int order,
                            Path mainFile, FileRead robotFile, SourcePos rootPos) {
        RobotResolver r = new RobotResolver(d, names, paramScope);
        Robot resolved = r.resolve(robot, order, mainFile, robotFile, rootPos);
        return new Resolved(resolved, r.broken, r.file);
    }

    private Robot resolve(XElement robot, int order, Path mainFile, FileRead robotFile, SourcePos rootPos) {
        if (robot == null) {
            d.error(rootPos, Msg.NO_ROBOT_SECTION);
            return null;
        }
        Attrs.allow(robot, d, Element.ROBOT.attributes());
        Attrs.noText(robot, d);
        XText file = Attrs.optional(robot, "file");
        XElement body = robot;
        String fileName = "";
        if (file != null) {
            if (!robot.children().isEmpty()) {
                d.error(robot.pos(), Msg.ROBOT_FILE_AND_ELEMENTS);
                return null;
            }
            Path p = Includes.resolve(mainFile, file.value().trim());
            this.file = p;
            if (robotFile.ioError() != null) {
                d.error(file.pos(), Msg.CANNOT_READ_ROBOT_FILE, p, robotFile.ioError());
                return null;
            }
            robotFile.diagnostics().forEach(d::report);
            body = robotFile.root();
            if (body == null) {
                return null;
            }
            if (!body.name().equals("robot")) {
                d.error(body.pos(), Msg.ROBOT_FILE_ROOT, body.name());
                return null;
            }
            Attrs.allow(body, d, Element.SECTION.attributes());
            Attrs.noText(body, d);
            fileName = file.value().trim();
        }
        return resolveBody(body, order, file == null ? null : robot.pos(), fileName);
    }

    private Robot resolveBody(XElement body, int order, SourcePos anchor, String fileName) {
        XElement structure = null;
        XElement sensorsEl = null;
        XElement actuatorsEl = null;
        for (XElement c : body.children()) {
            switch (c.name()) {
                case "structure":
                    structure = duplicate(structure, c);
                    break;
                case "sensors":
                    sensorsEl = duplicate(sensorsEl, c);
                    break;
                case "actuators":
                    actuatorsEl = duplicate(actuatorsEl, c);
                    break;
                default:
                    d.error(c.pos(), Msg.UNKNOWN_ROBOT_ELEMENT, c.name());
            }
        }
        if (structure == null) {
            d.error(body.pos(), Msg.ROBOT_NEEDS_STRUCTURE);
            return null;
        }
        preScan(structure);
        structure(structure, order, anchor);
        if (!groups.containsKey("all")) {
            groups.put("all", new Group("all", new ArrayList<>(modules), "", true, body.pos()));
        }
        if (sensorsEl != null) {
            declarations(sensorsEl, "sensor", Vocabulary.SENSOR_TYPES, Element.SENSOR,
                    (e, ids, elements) -> sensors.add(new SensorDecl(e.name(), ids, elements.value(), e.pos())));
        }
        if (actuatorsEl != null) {
            declarations(actuatorsEl, "actuator", Vocabulary.ACTUATOR_TYPES, Element.ACTUATOR,
                    (e, ids, elements) -> actuators.add(new ActuatorDecl(e.name(), ids, elements.value(), e.pos())));
        }
        return new Robot(new ArrayList<>(groups.values()), new ArrayList<>(modules), sensors, actuators, fileName,
                body.pos());
    }

    private XElement duplicate(XElement previous, XElement c) {
        if (previous != null) {
            d.error(c.pos(), Msg.ROBOT_PART_TWICE, c.name());
            return previous;
        }
        Attrs.allow(c, d, Element.ROBOT_PART.attributes());
        Attrs.noText(c, d);
        return c;
    }

    private void structure(XElement s, int order, SourcePos anchor) {
        int index = 0;
        for (XElement g : s.children()) {
            index++;
            Attrs.allow(g, d, Element.GROUP.attributes());
            Attrs.noText(g, d);
            Attrs.noChildren(g, d);
            String name = g.name();
            boolean ok = Attrs.validName(name, "group", g.pos(), d);
            names.define(name, "group", Declarations.order(order, index, 0), anchor == null ? g.pos() : anchor, g.pos(), "");
            XText elements = Attrs.require(g, "elements", d);
            if (elements == null || !ok || groups.containsKey(name)) {
                continue;
            }
            List<Integer> ids = elements(elements, true, Msg.named("group", name));
            if (ids != null) {
                groups.put(name, new Group(name, ids, elements.value(), false, g.pos()));
                modules.addAll(ids);
            } else {
                broken.add(name);
            }
        }
    }

    /** Expands an element list; {@code structure} selects the rules of §13 rule 11. */
    private List<Integer> elements(XText text, boolean structure, Message what) {
        List<Integer> out = new ArrayList<>();
        java.util.Set<Integer> seen = new java.util.HashSet<>();
        boolean ok = true;
        for (XText item : ListItem.split(text, ',')) {
            String v = item.value();
            List<Integer> ids;
            if (v.isEmpty()) {
                d.error(item.pos(), Msg.EMPTY_ELEMENT_ITEM, what);
                ok = false;
                continue;
            } else if (v.matches("\\d+")) {
                // leading zeros do not change the value (007 is module 7); compare the value, not the length
                String digits = v.replaceFirst("^0+(?=\\d)", "");
                if (digits.length() > 5 || Integer.parseInt(digits) > MAX_ID) {
                    d.error(item.pos(), Msg.MODULE_ID_TOO_LARGE, v, MAX_ID);
                    ok = false;
                    continue;
                }
                ids = List.of(Integer.parseInt(digits));
            } else if (v.contains("..")) {
                ids = range(item);
            } else {
                ids = groupRef(item, structure);
            }
            if (ids == null) {
                ok = false;
                continue;
            }
            for (int id : ids) {
                if (!seen.add(id)) {
                    d.error(item.pos(), Msg.MODULE_TWICE, id, what);
                    ok = false;
                } else {
                    out.add(id);
                }
            }
        }
        if (ok && out.isEmpty()) {
            d.error(text.pos(), Msg.ELEMENTS_EMPTY, what);
            return null;
        }
        return ok ? out : null;
    }

    private List<Integer> range(XText item) {
        int dots = item.value().indexOf("..");
        Integer a = rangeEnd(ListItem.trim(item, 0, dots));
        Integer b = rangeEnd(ListItem.trim(item, dots + 2, item.value().length()));
        if (a == null || b == null) {
            return null;
        }
        List<Integer> ids = new ArrayList<>();
        int step = a <= b ? 1 : -1;
        for (int i = a; ; i += step) {
            ids.add(i);
            if (i == b) {
                break;
            }
        }
        return ids;
    }

    private Integer rangeEnd(XText t) {
        ExprCompiler.Result r = ExprCompiler.compile(t, paramScope, d);
        if (r == null) {
            return null;
        }
        Expression e = r.expression();
        if (!e.isConstant()) {
            d.error(t.pos(), Msg.RANGE_END_NOT_CONSTANT, t.value());
            return null;
        }
        double v = e.eval(null);
        if (v != Math.rint(v) || v < 0) {
            d.error(t.pos(), Msg.RANGE_END_NOT_WHOLE, t.value(), Numbers.format(v));
            return null;
        }
        if (v > MAX_ID) {
            d.error(t.pos(), Msg.RANGE_END_TOO_LARGE, t.value(), Numbers.format(v), MAX_ID);
            return null;
        }
        return (int) v;
    }

    private List<Integer> groupRef(XText item, boolean structure) {
        String name = item.value();
        if (name.equals("all") && structure && !groups.containsKey("all")) {
            d.error(item.pos(), Msg.ALL_IN_STRUCTURE);
            return null;
        }
        Group g = groups.get(name);
        if (g != null) {
            return g.modules();
        }
        if (broken.contains(name)) {
            return null;
        }
        if (!Attrs.isName(name)) {
            d.error(item.pos(), Msg.NOT_AN_ELEMENT, name);
        } else if (structure && laterNames.contains(name)) {
            d.error(item.pos(), Msg.GROUP_DEFINED_LATER, name);
        } else {
            d.error(item.pos(), Msg.GROUP_NOT_DEFINED, name, Names.suggest(name, groups.keySet()));
        }
        return null;
    }

    private final java.util.Set<String> laterNames = new java.util.HashSet<>();

    /** Remembers every group name of the structure, so uses of later groups get a clear message. */
    private void preScan(XElement structure) {
        structure.children().forEach(g -> laterNames.add(g.name()));
    }

    /** Receives one well-formed declaration of {@code <sensors>} or {@code <actuators>}. */
    private interface Declared {
        void add(XElement e, List<Integer> ids, XText elements);
    }

    /** Reads the entries of {@code <sensors>} or {@code <actuators>} (PARSL.md §2): each a known type, once. */
    private void declarations(XElement section, String kind, List<String> types, Element element, Declared out) {
        java.util.Set<String> seen = new java.util.HashSet<>();
        for (XElement e : section.children()) {
            Attrs.noText(e, d);
            Attrs.noChildren(e, d);
            if (!types.contains(e.name())) {
                d.error(e.pos(), Msg.NOT_IMPLEMENTED, Msg.named(kind, e.name()), String.join(", ", types));
                continue;
            }
            Attrs.allow(e, d, element.attributes());
            if (!seen.add(e.name())) {
                d.error(e.pos(), Msg.DECLARED_TWICE_IN, Msg.named(kind, e.name()), section.name());
                continue;
            }
            XText elements = Attrs.require(e, "elements", d);
            List<Integer> ids = elements == null ? null : elements(elements, false, Msg.named(kind, e.name()));
            if (ids == null) {
                continue;
            }
            boolean ok = true;
            for (int id : ids) {
                if (!modules.contains(id)) {
                    d.error(elements.pos(), Msg.CARRIER_NOT_IN_STRUCTURE, id, e.name(), Msg.kind(kind));
                    ok = false;
                }
            }
            if (ok) {
                out.add(e, ids, elements);
            }
        }
    }
}
