package org.parpe.core.load;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;
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
import org.parpe.core.model.Interp;
import org.parpe.core.model.StateDef;
import org.parpe.core.model.Timing;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XText;

/** Resolves {@code <states>} (PARSL.md §5) and {@code <automata>} (§6). */
final class StateResolver {
    /**
     * The resolved states and automata.
     *
     * @param states   the named states in document order
     * @param automata the automata in document order
     * @param locals   the local sensor references of each automaton (its states' and times' expressions)
     * @param broken   states and automata defined with errors: uses of them are not reported again
     */
    record Resolved(Map<String, StateDef> states, Map<String, Automaton> automata,
                    Map<String, List<ExprCompiler.LocalUse>> locals, java.util.Set<String> broken) {
        Resolved {
            states = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(states));
            automata = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(automata));
            locals = Map.copyOf(locals);
            broken = java.util.Set.copyOf(broken);
        }
    }

    private final Map<String, StateDef> states = new LinkedHashMap<>();
    private final Map<String, Automaton> automata = new LinkedHashMap<>();
    private final Map<String, List<ExprCompiler.LocalUse>> locals = new HashMap<>();
    private final Map<String, List<ExprCompiler.LocalUse>> stateLocals = new HashMap<>();
    private final Map<String, XElement> stateElements = new HashMap<>();
    private final java.util.Set<String> broken = new java.util.HashSet<>();
    private final DiagnosticSink d;
    private final Scope scope;

    private StateResolver(DiagnosticSink d, Scope moduleScope) {
        this.d = d;
        this.scope = moduleScope;
    }

    /** Resolves the {@code <states>} and then the {@code <automata>} sections, in {@code moduleScope}. */
    static Resolved resolve(DiagnosticSink d, Scope moduleScope, List<Includes.Section> stateSections,
                            List<Includes.Section> automataSections) {
        StateResolver r = new StateResolver(d, moduleScope);
        r.sections(stateSections, r::state);
        r.sections(automataSections, r::automaton);
        return new Resolved(r.states, r.automata, r.locals, r.broken);
    }

    /** Checks each section's own attributes and text, and hands each child element with its section to {@code each}. */
    private void sections(List<Includes.Section> sections, BiConsumer<XElement, Includes.Section> each) {
        for (Includes.Section s : sections) {
            Attrs.allow(s.element(), d, Element.SECTION.attributes());
            Attrs.noText(s.element(), d);
            for (XElement e : s.element().children()) {
                each.accept(e, s);
            }
        }
    }

    private void state(XElement e, Includes.Section s) {
        Attrs.allow(e, d, Element.STATE.attributes());
        Attrs.noText(e, d);
        Attrs.noChildren(e, d);
        String name = e.name();
        boolean ok = Attrs.validName(name, "state", e.pos(), d);
        if (stateElements.containsKey(name)) {
            d.error(s.reportAt(e.pos()), Msg.ALREADY_DEFINED, Msg.named("state", name), Msg.definedAt(s.anchor(), e.pos()),
                    stateElements.get(name).pos());
            return;
        }
        stateElements.put(name, e);
        XText angles = Attrs.require(e, "angles", d);
        Interp interp = Interp.LINEAR;
        XText it = Attrs.optional(e, "interp");
        if (it != null) {
            try {
                interp = Interp.valueOf(it.value().trim().toUpperCase(java.util.Locale.ROOT));
            } catch (IllegalArgumentException ex) {
                d.error(it.pos(), Msg.BAD_INTERP, it.value());
                ok = false;
            }
        }
        List<Integer> latch = plates(e, "latch");
        List<Integer> unlatch = plates(e, "unlatch");
        ok &= latch != null && unlatch != null && bothLists(e, latch, unlatch);
        List<ExprCompiler.LocalUse> uses = new ArrayList<>();
        List<Expression> list = angles == null ? null : expressions(angles, uses, Msg.named("state", name));
        if (ok && list != null) {
            states.put(name, new StateDef(name, list, interp, latch, unlatch, e.pos()));
            stateLocals.put(name, uses);
        } else {
            broken.add(name);
        }
    }

    /**
     * The plates listed by a state's {@code latch} or {@code unlatch} attribute (PARSL.md §14),
     * ascending and each once; empty without the attribute, {@code null} after errors.
     */
    private List<Integer> plates(XElement e, String attribute) {
        XText text = Attrs.optional(e, attribute);
        if (text == null) {
            return List.of();
        }
        java.util.TreeSet<Integer> out = new java.util.TreeSet<>();
        boolean ok = true;
        for (XText item : ListItem.split(text, ',')) {
            int plate = Vocabulary.PLATES.indexOf(item.value());
            if (plate < 0) {
                if (item.value().isEmpty()) {
                    d.error(item.pos(), Msg.EMPTY_PLATE_ITEM, attribute, e.name());
                } else {
                    d.error(item.pos(), Msg.BAD_PLATE, attribute, e.name(), item.value());
                }
                ok = false;
            } else {
                out.add(plate);
            }
        }
        return ok ? List.copyOf(out) : null;
    }

    /** Reports a plate that one state both latches and unlatches; false if there is one. */
    private boolean bothLists(XElement e, List<Integer> latch, List<Integer> unlatch) {
        for (int plate : latch) {
            if (unlatch.contains(plate)) {
                d.error(Attrs.optional(e, "unlatch").pos(), Msg.LATCH_AND_UNLATCH, e.name(), plate);
                return false;
            }
        }
        return true;
    }

    /** Compiles a comma list of angle expressions; {@code null} after errors. */
    private List<Expression> expressions(XText text, List<ExprCompiler.LocalUse> uses, Message what) {
        List<Expression> out = new ArrayList<>();
        boolean ok = true;
        for (XText item : ListItem.split(text, ',')) {
            if (item.value().isEmpty()) {
                d.error(item.pos(), Msg.EMPTY_ANGLE_ITEM, what);
                ok = false;
                continue;
            }
            ExprCompiler.Result r = ExprCompiler.compile(item, scope, d);
            if (r == null) {
                ok = false;
            } else {
                out.add(r.expression());
                uses.addAll(r.locals());
            }
        }
        return ok ? out : null;
    }

    private void automaton(XElement e, Includes.Section s) {
        Attrs.allow(e, d, Element.AUTOMATON.attributes());
        Attrs.noChildren(e, d);
        String name = e.name();
        if (!Attrs.validName(name, "automaton", e.pos(), d)) {
            return;
        }
        if (automata.containsKey(name) || locals.containsKey(name)) {
            d.error(s.reportAt(e.pos()), Msg.ALREADY_DEFINED, Msg.named("automaton", name), Msg.definedAt(s.anchor(), e.pos()),
                    automata.containsKey(name) ? automata.get(name).pos() : Message.of(Msg.AN_EARLIER_PLACE));
            return;
        }
        XText statesAttr = Attrs.optional(e, "states");
        boolean table = !e.texts().isEmpty();
        List<ExprCompiler.LocalUse> uses = new ArrayList<>();
        locals.put(name, uses);
        broken.add(name);
        List<StateDef> list;
        if (statesAttr != null && table) {
            d.error(e.pos(), Msg.STATES_AND_ROWS, name);
            return;
        } else if (statesAttr != null) {
            list = stateList(statesAttr, uses);
        } else if (table) {
            list = rows(e, name, uses);
        } else {
            d.error(e.pos(), Msg.NEEDS_STATES_OR_ROWS, name);
            return;
        }
        if (list == null) {
            return;
        }
        XText timesAttr = Attrs.optional(e, "times");
        List<Timing> times = timesAttr == null ? defaultTimes(list.size()) : times(timesAttr, list.size(), uses, name);
        if (times != null) {
            automata.put(name, new Automaton(name, list, times, table, timesAttr == null ? null : timesAttr.value(), e.pos()));
            broken.remove(name);
        }
    }

    private List<StateDef> stateList(XText attr, List<ExprCompiler.LocalUse> uses) {
        List<StateDef> out = new ArrayList<>();
        boolean ok = true;
        for (XText item : ListItem.split(attr, ',')) {
            StateDef st = states.get(item.value());
            if (item.value().isEmpty()) {
                d.error(item.pos(), Msg.EMPTY_STATE_ITEM);
                ok = false;
            } else if (st == null && broken.contains(item.value())) {
                ok = false;
            } else if (st == null) {
                d.error(item.pos(), Msg.STATE_NOT_DEFINED, item.value(), Names.suggest(item.value(), states.keySet()));
                ok = false;
            } else {
                out.add(st);
                uses.addAll(stateLocals.getOrDefault(st.name(), List.of()));
            }
        }
        return ok ? out : null;
    }

    private List<StateDef> rows(XElement e, String name, List<ExprCompiler.LocalUse> uses) {
        List<StateDef> out = new ArrayList<>();
        boolean ok = true;
        for (XText text : e.texts()) {
            for (XText line : ListItem.split(text, '\n')) {
                for (XText row : ListItem.split(line, ';')) {
                    if (row.value().isEmpty()) {
                        continue;
                    }
                    String rowName = name + "[" + out.size() + "]";
                    List<Expression> angles = expressions(row, uses, Message.of(Msg.GAIT_TABLE_ROW, out.size(), name));
                    if (angles == null) {
                        ok = false;
                        out.add(null);
                    } else {
                        out.add(new StateDef(rowName, angles, Interp.LINEAR, row.pos()));
                    }
                }
            }
        }
        return ok ? out : null;
    }

    private static List<Timing> defaultTimes(int n) {
        List<Timing> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            out.add(new Timing(Expression.constant(1, "1"), null));
        }
        return out;
    }

    private List<Timing> times(XText attr, int n, List<ExprCompiler.LocalUse> uses, String name) {
        List<XText> items = ListItem.split(attr, ',');
        if (items.size() != n) {
            d.error(attr.pos(), Msg.TIMES_COUNT, name, items.size(), Message.of(n == 1 ? Msg.ONE_STATE : Msg.N_STATES, n));
            return null;
        }
        List<Timing> out = new ArrayList<>();
        boolean ok = true;
        for (XText item : items) {
            String v = item.value();
            XText t = item;
            XText cond = null;
            int open = v.indexOf('[');
            if (open >= 0) {
                if (!v.endsWith("]")) {
                    d.error(item.pos(), Msg.BAD_TIME_CONDITION, v);
                    ok = false;
                    continue;
                }
                t = ListItem.trim(item, 0, open);
                cond = ListItem.trim(item, open + 1, v.length() - 1);
            }
            ExprCompiler.Result tr = t.value().isEmpty() ? null : ExprCompiler.compile(t, scope, d);
            if (t.value().isEmpty()) {
                d.error(item.pos(), Msg.EMPTY_DURATION, name);
            }
            ExprCompiler.Result cr = cond == null ? null : ExprCompiler.compile(cond, scope, d);
            if (tr == null || cond != null && cr == null) {
                ok = false;
                continue;
            }
            uses.addAll(tr.locals());
            if (cr != null) {
                uses.addAll(cr.locals());
            }
            out.add(new Timing(tr.expression(), cr == null ? null : cr.expression()));
        }
        return ok ? out : null;
    }
}
