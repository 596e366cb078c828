package org.parpe.core.load;

import java.util.ArrayList;
import java.util.LinkedHashMap;
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
import org.parpe.core.model.MainDef;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Robot;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XText;

/** Resolves {@code <main>} (PARSL.md §8): cycles, entries, macro values. */
final class MainResolver {
    private final DiagnosticSink d;
    private final ScriptLoader.Scopes scopes;
    private final BehaviorResolver.Resolved behaviors;
    private final InstanceChecks checks;
    private final Robot robot;
    private final Map<String, Automaton> automata;

    MainResolver(DiagnosticSink d, ScriptLoader.Scopes scopes, BehaviorResolver.Resolved behaviors, InstanceChecks checks,
                 Robot robot, Map<String, Automaton> automata) {
        this.d = d;
        this.scopes = scopes;
        this.behaviors = behaviors;
        this.checks = checks;
        this.robot = robot;
        this.automata = automata;
    }

    MainDef resolve(XElement main, Map<String, Double> params) {
        Attrs.allow(main, d, Element.MAIN.attributes());
        Attrs.noText(main, d);
        XText cyclesText = Attrs.optional(main, "cycles");
        long cycles = cyclesText == null ? 1 : cycles(cyclesText);
        List<MainEntry> entries = new ArrayList<>();
        for (XElement e : main.children()) {
            MainEntry entry = entry(e);
            if (entry != null) {
                entries.add(entry);
            }
        }
        return new MainDef(cycles, cyclesText == null ? null : cyclesText.value(), entries, main.pos());
    }

    private long cycles(XText t) {
        if (t.value().trim().equals(Vocabulary.FOREVER)) {
            return MainDef.FOREVER;
        }
        ExprCompiler.Result r = ExprCompiler.compile(t, scopes.scope(Scope.Kind.PARAMETERS_ONLY, Map.of(), Set.of()), d);
        if (r == null) {
            return 1;
        }
        double v = r.expression().isConstant() ? r.expression().eval(null) : Double.NaN;
        if (v != Math.rint(v) || v < 1) {
            d.error(t.pos(), Msg.BAD_CYCLES, t.value());
            return 1;
        }
        return (long) v;
    }

    private MainEntry entry(XElement e) {
        Attrs.noText(e, d);
        Attrs.noChildren(e, d);
        BehaviorResolver.Info info = behaviors.behaviors().get(e.name());
        if (info == null && behaviors.broken().contains(e.name())) {
            return null;
        }
        if (info == null) {
            d.error(e.pos(), Msg.BEHAVIOR_NOT_DEFINED, e.name(), Names.suggest(e.name(), behaviors.behaviors().keySet()));
            return null;
        }
        Behavior b = info.model();
        List<String> allowed = new ArrayList<>(Element.ENTRY.attributes());
        allowed.addAll(b.macros());
        Attrs.allow(e, d, allowed);
        Scope scope = scopes.scope(Scope.Kind.ENTRY, Map.of(), Set.of());
        Expression time = optional(e, "time", scope);
        Expression exit = optional(e, "exit", scope);
        Map<String, MainEntry.MacroArg> args = new LinkedHashMap<>();
        boolean ok = true;
        for (String m : b.macros()) {
            XElement.XAttr a = e.attr(m);
            if (a == null) {
                d.error(e.pos(), Msg.MACRO_VALUE_MISSING, e.name(), m);
                ok = false;
                continue;
            }
            MainEntry.MacroArg arg = info.groupMacros().contains(m) ? groupArg(m, a) : exprArg(m, a, scope);
            if (arg == null) {
                ok = false;
            } else {
                args.put(m, arg);
            }
        }
        if (!ok) {
            return null;
        }
        checks.checkBehavior(b.name(), info.instances(), args);
        List<MainEntry.MacroArg> macros = new ArrayList<>(args.values());
        List<MainEntry.Binding> bindings = new ArrayList<>();
        bind(b.items(), new ArrayList<>(), macros, bindings);
        return new MainEntry(b.name(), b, time, exit, macros, bindings, e.pos());
    }

    /**
     * Resolves every instance under {@code items} for one entry: its automaton, and its group
     * and mirror flag after the entry's macro values (an instance whose names did not resolve has
     * been reported and gets no binding).
     */
    private void bind(List<BehaviorItem> items, List<Conditional> conds, List<MainEntry.MacroArg> macros,
                      List<MainEntry.Binding> out) {
        for (BehaviorItem item : items) {
            if (item instanceof Conditional c) {
                conds.add(c);
                bind(c.items(), conds, macros, out);
                conds.remove(conds.size() - 1);
                continue;
            }
            Instance i = (Instance) item;
            MainEntry.GroupRef ref = i.groupRef().through(macros);
            Group group = robot == null ? null : robot.group(ref.name()).orElse(null);
            Automaton automaton = i.automaton();
            if (group != null && automaton != null) {
                out.add(new MainEntry.Binding(i, automaton, group, ref.mirror(), conds));
            }
        }
    }

    private Expression optional(XElement e, String attr, Scope scope) {
        XText t = Attrs.optional(e, attr);
        if (t == null) {
            return null;
        }
        ExprCompiler.Result r = ExprCompiler.compile(t, scope, d);
        return r == null ? null : r.expression();
    }

    private MainEntry.MacroArg groupArg(String macro, XElement.XAttr a) {
        String v = a.value().value().trim();
        MainEntry.GroupRef written = MainEntry.GroupRef.parse(v);
        String base = written.name();
        if (robot != null && robot.group(base).isEmpty()) {
            List<String> known = robot.groups().stream().map(g -> g.name()).toList();
            d.error(a.value().pos(), Msg.MACRO_NOT_A_GROUP, macro, base, Names.suggest(base, known));
            return null;
        }
        return new MainEntry.MacroArg(macro, v, base, written.mirror(), null, a.value().pos());
    }

    private MainEntry.MacroArg exprArg(String macro, XElement.XAttr a, Scope scope) {
        ExprCompiler.Result r = ExprCompiler.compile(a.value(), scope, d);
        return r == null ? null : new MainEntry.MacroArg(macro, a.value().value().trim(), null, false, r.expression(), a.value().pos());
    }
}
