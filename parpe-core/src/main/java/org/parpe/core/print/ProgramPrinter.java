package org.parpe.core.print;

import java.util.List;
import java.util.function.Consumer;
import java.util.stream.Collectors;
import org.parpe.core.edit.ElementWriter;
import org.parpe.core.expr.Expression;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.BehaviorItem;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.Control;
import org.parpe.core.model.Group;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Interp;
import org.parpe.core.model.MainDef;
import org.parpe.core.model.MainEntry;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Parameter;
import org.parpe.core.model.Program;
import org.parpe.core.model.ActuatorDecl;
import org.parpe.core.model.SensorDecl;
import org.parpe.core.model.StateDef;
import org.parpe.core.model.Timing;

/**
 * Prints a {@link Program} as a canonical, self-contained PARSL document: includes and robot
 * files are inlined, expressions are printed as written. Loading the output gives an equal
 * model (positions aside); the IDE uses it for "save as single file" and recordings.
 */
public final class ProgramPrinter {
    private final StringBuilder out = new StringBuilder();

    private ProgramPrinter() {
    }

    /** The program as PARSL text. */
    public static String print(Program p) {
        ProgramPrinter w = new ProgramPrinter();
        w.program(p);
        return w.out.toString();
    }

    private void program(Program p) {
        codes = p.radioWords();
        line(0, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
        open(0, "program");
        robot(p);
        section("parameters", p.parameters(), this::parameter);
        section("controls", p.controls(), this::control);
        if (p.main() != null) {
            main(p.main());
        }
        section("behaviors", p.behaviors(), this::behavior);
        section("automata", p.automata(), this::automaton);
        section("states", p.states(), this::state);
        close(0, "program");
    }

    /** A top-level section {@code <tag>} with an element per item, or nothing where there are none. */
    private <T> void section(String tag, List<T> items, Consumer<T> each) {
        if (!items.isEmpty()) {
            open(1, tag);
            items.forEach(each);
            close(1, tag);
        }
    }

    private void robot(Program p) {
        open(1, "robot");
        open(2, "structure");
        for (Group g : p.robot().groups()) {
            if (!g.implicit()) {
                line(3, tag(g.name()).attr("elements", g.elements()).empty());
            }
        }
        close(2, "structure");
        if (!p.robot().sensors().isEmpty()) {
            open(2, "sensors");
            for (SensorDecl s : p.robot().sensors()) {
                line(3, tag(s.type()).attr("elements", s.elements()).empty());
            }
            close(2, "sensors");
        }
        if (!p.robot().actuators().isEmpty()) {
            open(2, "actuators");
            for (ActuatorDecl a : p.robot().actuators()) {
                line(3, tag(a.type()).attr("elements", a.elements()).empty());
            }
            close(2, "actuators");
        }
        close(1, "robot");
    }

    private void parameter(Parameter p) {
        ElementWriter e = tag(p.name()).attr("value", Numbers.format(p.value()));
        if (p.min() != null) {
            e.attr("min", Numbers.format(p.min()));
        }
        if (p.max() != null) {
            e.attr("max", Numbers.format(p.max()));
        }
        if (!p.label().isEmpty()) {
            e.attr("label", p.label());
        }
        line(2, e.empty());
    }

    private void control(Control c) {
        ElementWriter e = tag(c.name()).attr("type", c.type().word());
        if (c.type() == Control.ControlType.RADIO) {
            e.attr("values", String.join(", ", c.words())).attr("value", wordOf(c));
        } else {
            if (c.min() != null) {
                e.attr("min", Numbers.format(c.min())).attr("max", Numbers.format(c.max()));
            }
            e.attr("value", Numbers.format(c.value()));
            if (c.step() != null) {
                e.attr("step", Numbers.format(c.step()));
            }
        }
        if (!c.keys().isEmpty()) {
            e.attr("keys", String.join(", ", c.keys()));
        }
        if (!c.label().isEmpty()) {
            e.attr("label", c.label());
        }
        line(2, e.empty());
    }

    private String wordOf(Control c) {
        // the initial word is the one whose code is the control's value; codes follow first appearance
        return c.words().stream().filter(w -> codes.containsKey(w) && codes.get(w) == c.value()).findFirst()
                .orElse(c.words().get(0));
    }

    private java.util.Map<String, Integer> codes = java.util.Map.of();

    private void main(MainDef m) {
        ElementWriter main = tag("main");
        if (m.cyclesText() != null) {
            main.attr("cycles", m.cyclesText());
        }
        line(1, main.open());
        for (MainEntry e : m.entries()) {
            ElementWriter entry = tag(e.behavior());
            opt(entry, "time", e.time());
            opt(entry, "exit", e.exit());
            for (MainEntry.MacroArg arg : e.macros()) {
                entry.attr(arg.name(), arg.text());
            }
            line(2, entry.empty());
        }
        close(1, "main");
    }

    private void behavior(Behavior b) {
        ElementWriter e = tag(b.name());
        if (!b.macros().isEmpty()) {
            e.attr("macros", String.join(", ", b.macros()));
        }
        if (b.items().isEmpty()) {
            line(2, e.empty());
            return;
        }
        line(2, e.open());
        items(b.items(), 3);
        close(2, b.name());
    }

    private void items(List<BehaviorItem> items, int depth) {
        for (BehaviorItem item : items) {
            if (item instanceof Conditional) {
                Conditional c = (Conditional) item;
                line(depth, tag("if").attr("cond", c.condition().text()).open());
                items(c.items(), depth + 1);
                close(depth, "if");
            } else {
                Instance i = (Instance) item;
                ElementWriter e = tag(i.name()).attr("group", i.group());
                opt(e, "phase", i.phase());
                opt(e, "offset", i.offset());
                opt(e, "period", i.period());
                opt(e, "start", i.start());
                opt(e, "cycles", i.cycles());
                line(depth, e.empty());
            }
        }
    }

    private void automaton(Automaton a) {
        ElementWriter e = tag(a.name());
        if (!a.table()) {
            e.attr("states", a.states().stream().map(StateDef::name).collect(Collectors.joining(", ")));
        }
        if (a.timesText() != null) {
            e.attr("times", a.times().stream().map(ProgramPrinter::timing).collect(Collectors.joining(", ")));
        }
        if (!a.table()) {
            line(2, e.empty());
            return;
        }
        line(2, e.open());
        for (StateDef row : a.states()) {
            line(3, ElementWriter.text(row.angles().stream().map(Expression::text).collect(Collectors.joining(", "))));
        }
        close(2, a.name());
    }

    private static String timing(Timing t) {
        return t.duration().text() + (t.exit() == null ? "" : "[" + t.exit().text() + "]");
    }

    private void state(StateDef s) {
        ElementWriter e = tag(s.name()).attr("angles", s.angles().stream().map(Expression::text)
                .collect(Collectors.joining(", ")));
        if (s.interp() != Interp.LINEAR) {
            e.attr("interp", s.interp().word());
        }
        plates(e, "latch", s.latch());
        plates(e, "unlatch", s.unlatch());
        line(2, e.empty());
    }

    private static void plates(ElementWriter e, String name, List<Integer> plates) {
        if (!plates.isEmpty()) {
            e.attr(name, plates.stream().map(String::valueOf).collect(Collectors.joining(", ")));
        }
    }

    private static void opt(ElementWriter e, String name, Expression x) {
        if (x != null) {
            e.attr(name, x.text());
        }
    }

    private static ElementWriter tag(String name) {
        return ElementWriter.tag(name);
    }

    private void open(int depth, String tag) {
        line(depth, ElementWriter.tag(tag).open());
    }

    private void close(int depth, String tag) {
        line(depth, ElementWriter.close(tag));
    }

    private void line(int depth, String text) {
        out.append("  ".repeat(depth)).append(text).append('\n');
    }
}
