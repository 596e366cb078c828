package org.parpe.core.load;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.expr.ExprCompiler;
import org.parpe.core.expr.Expression;
import org.parpe.core.expr.Names;
import org.parpe.core.expr.Scope;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import org.parpe.core.lang.Vocabulary.Element;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.BehaviorItem;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.Group;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Robot;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XText;

/** Resolves {@code <behaviors>} (PARSL.md §7) and the static checks on their instances. */
final class BehaviorResolver {
    private static final List<String> INSTANCE_ATTRS = Element.INSTANCE.attributes();

    /** What the checks need to know of an instance. */
    record InstanceInfo(Instance model, boolean conditional, String base, boolean mirror, boolean macroGroup) {
    }

    /** A resolved behavior with its macros split by kind. */
    record Info(Behavior model, Set<String> groupMacros, List<InstanceInfo> instances) {
    }

    /**
     * The resolved behaviors.
     *
     * @param behaviors the behaviors in document order, by name
     * @param broken    behaviors defined with errors: entries that invoke them are not reported again
     */
    record Resolved(Map<String, Info> behaviors, Set<String> broken) {
        Resolved {
            behaviors = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(behaviors));
            broken = Set.copyOf(broken);
        }
    }

    private final Map<String, Info> behaviors = new LinkedHashMap<>();
    private final DiagnosticSink d;
    private final NameRegistry names;
    private final Robot robot;
    private final InstanceChecks checks;
    /** Builds a scope of a kind with the given macros (name → index) and group macros. */
    private final ScopeFactory scopes;
    private final Map<String, Automaton> automata;
    private final Set<String> brokenAutomata;
    private final Set<String> broken = new java.util.HashSet<>();
    private final Set<String> brokenGroups;

    /** Makes scopes for behavior expressions. */
    interface ScopeFactory {
        /** A scope of {@code kind} that also sees {@code macros} and knows {@code groupMacros}. */
        Scope scope(Scope.Kind kind, Map<String, Integer> macros, Set<String> groupMacros);
    }

    private int errorCount;

    private BehaviorResolver(DiagnosticSink d, NameRegistry names, RobotResolver.Resolved robot,
                             StateResolver.Resolved states, InstanceChecks checks, ScopeFactory scopes) {
        this.brokenAutomata = states.broken();
        this.brokenGroups = robot.broken();
        this.d = diag -> {
            if (diag.severity() == org.parpe.core.diag.Severity.ERROR) {
                errorCount++;
            }
            d.report(diag);
        };
        this.names = names;
        this.robot = robot.robot();
        this.automata = states.automata();
        this.checks = checks;
        this.scopes = scopes;
    }

    /**
     * Resolves the {@code <behaviors>} sections of a program whose robot, states and automata
     * are resolved; {@code checks} checks their instances, {@code scopes} makes their scopes.
     */
    static Resolved resolve(DiagnosticSink d, NameRegistry names, RobotResolver.Resolved robot,
                            StateResolver.Resolved states, InstanceChecks checks, ScopeFactory scopes,
                            List<Includes.Section> sections) {
        BehaviorResolver r = new BehaviorResolver(d, names, robot, states, checks, scopes);
        r.behaviors(sections);
        return new Resolved(r.behaviors, r.broken);
    }

    private void behaviors(List<Includes.Section> sections) {
        for (Includes.Section s : sections) {
            Attrs.allow(s.element(), d, Element.SECTION.attributes());
            Attrs.noText(s.element(), d);
            int index = 0;
            for (XElement e : s.element().children()) {
                behavior(e, s, ++index);
            }
        }
    }

    private void behavior(XElement e, Includes.Section s, int index) {
        Attrs.allow(e, d, Element.BEHAVIOR.attributes());
        Attrs.noText(e, d);
        String name = e.name();
        if (!Attrs.validName(name, "behavior", e.pos(), d)) {
            return;
        }
        if (behaviors.containsKey(name)) {
            d.error(s.reportAt(e.pos()), Msg.ALREADY_DEFINED, Msg.named("behavior", name), Msg.definedAt(s.anchor(), e.pos()),
                    behaviors.get(name).model().pos());
            return;
        }
        int before = errorCount;
        List<String> macros = macros(e, s, index);
        Set<String> groupMacros = new LinkedHashSet<>();
        collectGroupMacros(e, macros, groupMacros);
        Map<String, Integer> exprMacros = new LinkedHashMap<>();
        for (String m : macros) {
            if (!groupMacros.contains(m)) {
                exprMacros.put(m, macros.indexOf(m));
            }
        }
        List<InstanceInfo> infos = new ArrayList<>();
        List<BehaviorItem> items = items(e, false, exprMacros, groupMacros, infos);
        Behavior b = new Behavior(name, macros, items, e.pos());
        behaviors.put(name, new Info(b, groupMacros, infos));
        checks.checkBehavior(b.name(), infos, null);
        if (errorCount > before) {
            broken.add(name);
        }
    }

    private List<String> macros(XElement e, Includes.Section s, int index) {
        XText attr = Attrs.optional(e, "macros");
        List<String> out = new ArrayList<>();
        if (attr == null) {
            return out;
        }
        int k = 0;
        for (XText m : ListItem.split(attr, ',')) {
            String name = m.value();
            if (name.isEmpty()) {
                d.error(m.pos(), Msg.EMPTY_MACRO_ITEM);
            } else if (name.equals("time") || name.equals("exit")) {
                d.error(m.pos(), Msg.MACRO_NAME_TAKEN, name);
            } else if (Attrs.validName(name, "macro", m.pos(), d)) {
                if (out.contains(name)) {
                    d.error(m.pos(), Msg.MACRO_TWICE, name);
                    continue;
                }
                out.add(name);
                names.define(name, "macro", Declarations.order(s.order(), index, ++k), s.reportAt(m.pos()), m.pos(), e.name());
            }
        }
        return out;
    }

    private static void collectGroupMacros(XElement e, List<String> macros, Set<String> out) {
        for (XElement c : e.children()) {
            XElement.XAttr g = c.attr("group");
            if (!c.name().equals(Vocabulary.IF) && g != null) {
                String base = MainEntry.GroupRef.parse(g.value().value()).name();
                if (macros.contains(base)) {
                    out.add(base);
                }
            }
            if (c.name().equals(Vocabulary.IF)) {
                collectGroupMacros(c, macros, out);
            }
        }
    }

    private List<BehaviorItem> items(XElement parent, boolean conditional, Map<String, Integer> macros,
                                     Set<String> groupMacros, List<InstanceInfo> infos) {
        List<BehaviorItem> out = new ArrayList<>();
        for (XElement c : parent.children()) {
            if (c.name().equals(Vocabulary.IF)) {
                Attrs.allow(c, d, Element.CONDITIONAL.attributes());
                Attrs.noText(c, d);
                XText cond = Attrs.require(c, "cond", d);
                ExprCompiler.Result r = cond == null ? null
                        : ExprCompiler.compile(cond, scopes.scope(Scope.Kind.CONDITION, macros, groupMacros), d);
                List<BehaviorItem> inner = items(c, true, macros, groupMacros, infos);
                if (r != null) {
                    out.add(new Conditional(r.expression(), inner, c.pos()));
                }
            } else {
                Instance i = instance(c, conditional, macros, groupMacros, infos);
                if (i != null) {
                    out.add(i);
                }
            }
        }
        return out;
    }

    private Instance instance(XElement c, boolean conditional, Map<String, Integer> macros, Set<String> groupMacros,
                              List<InstanceInfo> infos) {
        Attrs.allow(c, d, INSTANCE_ATTRS);
        Attrs.noText(c, d);
        Attrs.noChildren(c, d);
        boolean ok = true;
        if (!automata.containsKey(c.name()) && brokenAutomata.contains(c.name())) {
            ok = false;
        } else if (!automata.containsKey(c.name())) {
            d.error(c.pos(), Msg.AUTOMATON_NOT_DEFINED, c.name(), Names.suggest(c.name(), automata.keySet()));
            ok = false;
        }
        XText group = Attrs.require(c, "group", d);
        String base = null;
        boolean mirror = false;
        if (group != null) {
            MainEntry.GroupRef written = MainEntry.GroupRef.parse(group.value());
            mirror = written.mirror();
            base = written.name();
            if (!groupMacros.contains(base) && (robot == null || brokenGroups.contains(base))) {
                ok = false;
            } else if (!groupMacros.contains(base) && robot.group(base).isEmpty()) {
                List<String> known = new ArrayList<>();
                robot.groups().forEach(x -> known.add(x.name()));
                known.addAll(groupMacros);
                d.error(group.pos(), Msg.GROUP_NOT_DEFINED, base, Names.suggest(base, known));
                ok = false;
            }
        }
        Scope scope = scopes.scope(Scope.Kind.INSTANCE, macros, groupMacros);
        Expression[] e = new Expression[5];
        for (int k = 1; k < INSTANCE_ATTRS.size(); k++) {
            XText v = Attrs.optional(c, INSTANCE_ATTRS.get(k));
            if (v != null) {
                ExprCompiler.Result r = ExprCompiler.compile(v, scope, d);
                ok &= r != null;
                e[k - 1] = r == null ? null : r.expression();
            }
        }
        if (!ok || group == null) {
            return null;
        }
        Group on = groupMacros.contains(base) ? null : robot.group(base).orElseThrow();
        Instance inst = new Instance(automata.get(c.name()), group.value().trim(), on, e[0], e[1], e[2], e[3], e[4], c.pos());
        infos.add(new InstanceInfo(inst, conditional, base, mirror, groupMacros.contains(base)));
        return inst;
    }
}
