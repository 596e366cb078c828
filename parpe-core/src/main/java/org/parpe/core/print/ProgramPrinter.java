package org.parpe.core.print;

import java.util.List;
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
        line(0, "<program>");
        robot(p);
        if (!p.parameters().isEmpty()) {
            line(1, "<parameters>");
            p.parameters().forEach(this::parameter);
            line(1, "</parameters>");
        }
        if (!p.controls().isEmpty()) {
            line(1, "<controls>");
            p.controls().forEach(this::control);
            line(1, "</controls>");
        }
        if (p.main() != null) {
            main(p.main());
        }
        if (!p.behaviors().isEmpty()) {
            line(1, "<behaviors>");
            p.behaviors().forEach(this::behavior);
            line(1, "</behaviors>");
        }
        if (!p.automata().isEmpty()) {
            line(1, "<automata>");
            p.automata().forEach(this::automaton);
            line(1, "</automata>");
        }
        List<StateDef> named = p.states();
        if (!named.isEmpty()) {
            line(1, "<states>");
            named.forEach(this::state);
            line(1, "</states>");
        }
        line(0, "</program>");
    }

    private void robot(Program p) {
        line(1, "<robot>");
        line(2, "<structure>");
        for (Group g : p.robot().groups()) {
            if (!g.implicit()) {
                line(3, "<" + g.name() + attr("elements", g.elements()) + "/>");
            }
        }
        line(2, "</structure>");
        if (!p.robot().sensors().isEmpty()) {
            line(2, "<sensors>");
            for (SensorDecl s : p.robot().sensors()) {
                line(3, "<" + s.type() + attr("elements", s.elements()) + "/>");
            }
            line(2, "</sensors>");
        }
        if (!p.robot().actuators().isEmpty()) {
            line(2, "<actuators>");
            for (ActuatorDecl a : p.robot().actuators()) {
                line(3, "<" + a.type() + attr("elements", a.elements()) + "/>");
            }
            line(2, "</actuators>");
        }
        line(1, "</robot>");
    }

    private void parameter(Parameter p) {
        line(2, "<" + p.name() + attr("value", Numbers.format(p.value()))
                + (p.min() == null ? "" : attr("min", Numbers.format(p.min())))
                + (p.max() == null ? "" : attr("max", Numbers.format(p.max())))
                + (p.label().isEmpty() ? "" : attr("label", p.label())) + "/>");
    }

    private void control(Control c) {
        StringBuilder a = new StringBuilder(attr("type", c.type().word()));
        if (c.type() == Control.ControlType.RADIO) {
            a.append(attr("values", String.join(", ", c.words())));
            a.append(attr("value", wordOf(c)));
        } else {
            if (c.min() != null) {
                a.append(attr("min", Numbers.format(c.min()))).append(attr("max", Numbers.format(c.max())));
            }
            a.append(attr("value", Numbers.format(c.value())));
            if (c.step() != null) {
                a.append(attr("step", Numbers.format(c.step())));
            }
        }
        if (!c.keys().isEmpty()) {
            a.append(attr("keys", String.join(", ", c.keys())));
        }
        if (!c.label().isEmpty()) {
            a.append(attr("label", c.label()));
        }
        line(2, "<" + c.name() + a + "/>");
    }

    private String wordOf(Control c) {
        // the initial word is the one whose code is the control's value; codes follow first appearance
        return c.words().stream().filter(w -> codes.containsKey(w) && codes.get(w) == c.value()).findFirst()
                .orElse(c.words().get(0));
    }

    private java.util.Map<String, Integer> codes = java.util.Map.of();

    private void main(MainDef m) {
        line(1, "<main" + (m.cyclesText() == null ? "" : attr("cycles", m.cyclesText())) + ">");
        for (MainEntry e : m.entries()) {
            StringBuilder a = new StringBuilder();
            if (e.time() != null) {
                a.append(attr("time", e.time().text()));
            }
            if (e.exit() != null) {
                a.append(attr("exit", e.exit().text()));
            }
            for (MainEntry.MacroArg arg : e.macros()) {
                a.append(attr(arg.name(), arg.text()));
            }
            line(2, "<" + e.behavior() + a + "/>");
        }
        line(1, "</main>");
    }

    private void behavior(Behavior b) {
        String macros = b.macros().isEmpty() ? "" : attr("macros", String.join(", ", b.macros()));
        if (b.items().isEmpty()) {
            line(2, "<" + b.name() + macros + "/>");
            return;
        }
        line(2, "<" + b.name() + macros + ">");
        items(b.items(), 3);
        line(2, "</" + b.name() + ">");
    }

    private void items(List<BehaviorItem> items, int depth) {
        for (BehaviorItem item : items) {
            if (item instanceof Conditional) {
                Conditional c = (Conditional) item;
                line(depth, "<if" + attr("cond", c.condition().text()) + ">");
                items(c.items(), depth + 1);
                line(depth, "</if>");
            } else {
                Instance i = (Instance) item;
                line(depth, "<" + i.name() + attr("group", i.group()) + opt("phase", i.phase())
                        + opt("offset", i.offset()) + opt("period", i.period()) + opt("start", i.start())
                        + opt("cycles", i.cycles()) + "/>");
            }
        }
    }

    private void automaton(Automaton a) {
        String times = a.timesText() == null ? "" : attr("times", a.times().stream().map(ProgramPrinter::timing)
                .collect(Collectors.joining(", ")));
        if (!a.table()) {
            String states = a.states().stream().map(StateDef::name).collect(Collectors.joining(", "));
            line(2, "<" + a.name() + attr("states", states) + times + "/>");
            return;
        }
        line(2, "<" + a.name() + times + ">");
        for (StateDef row : a.states()) {
            line(3, ElementWriter.text(row.angles().stream().map(Expression::text).collect(Collectors.joining(", "))));
        }
        line(2, "</" + a.name() + ">");
    }

    private static String timing(Timing t) {
        return t.duration().text() + (t.exit() == null ? "" : "[" + t.exit().text() + "]");
    }

    private void state(StateDef s) {
        String angles = s.angles().stream().map(Expression::text).collect(Collectors.joining(", "));
        line(2, "<" + s.name() + attr("angles", angles)
                + (s.interp() == Interp.LINEAR ? "" : attr("interp", s.interp().word()))
                + plates("latch", s.latch()) + plates("unlatch", s.unlatch()) + "/>");
    }

    private static String plates(String name, List<Integer> plates) {
        return plates.isEmpty() ? "" : attr(name, plates.stream().map(String::valueOf).collect(Collectors.joining(", ")));
    }

    private static String opt(String name, Expression e) {
        return e == null ? "" : attr(name, e.text());
    }

    private static String attr(String name, String value) {
        return " " + name + "=\"" + ElementWriter.attributeText(value) + "\"";
    }

    private void line(int depth, String text) {
        out.append("  ".repeat(depth)).append(text).append('\n');
    }
}
