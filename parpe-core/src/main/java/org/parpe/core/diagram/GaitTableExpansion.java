package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.edit.EditRefused;
import org.parpe.core.edit.ElementWriter;
import org.parpe.core.edit.Replacement;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.edit.SectionEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.expr.Expression;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Group;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Interp;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;
import org.parpe.core.model.Timing;
import org.parpe.core.text.EditMsg;
import org.parpe.core.text.Message;

/**
 * "Expand to gait table": the gait table that drives the modules of a phase-automaton
 * instance as the instance does (PARSL.md §6 and §7.1). A row ends wherever any module enters
 * a state; each row gives every module (a column, in group order) the angle the module reaches
 * at the row's end on its straight line from the previous state's target to its state's
 * target, and lasts that part of the period. Played with phase 0 and offset 0 on the same group
 * (mirrored as the instance is), every module follows the same line as under the automaton once
 * it has finished the state it started part-way through, that is from one period on; before
 * that the automaton starts each module part-way into a state from where it stands, which a
 * table, whose modules all start at row 0, cannot express.
 */
public final class GaitTableExpansion {
    private static final double SAME = 1e-12;

    private GaitTableExpansion() {
    }

    /**
     * A gait table.
     *
     * @param rows    one angle per module (group order) per row, in degrees
     * @param seconds each row's duration
     */
    public record Table(List<double[]> rows, double[] seconds) {

        /** Each row as a line of the table's text: its angles, comma separated. */
        public List<String> rowTexts() {
            List<String> out = new ArrayList<>();
            for (double[] r : rows) {
                StringBuilder b = new StringBuilder();
                for (int k = 0; k < r.length; k++) {
                    b.append(k == 0 ? "" : ", ").append(Numbers.format(r[k]));
                }
                out.add(b.toString());
            }
            return out;
        }

        /** The {@code times} attribute: each row's seconds. */
        public String times() {
            StringBuilder b = new StringBuilder();
            for (int i = 0; i < seconds.length; i++) {
                b.append(i == 0 ? "" : ", ").append(Numbers.format(seconds[i]));
            }
            return b.toString();
        }
    }

    /**
     * The table equivalent to {@code in} (an instance of a phase automaton of {@code p}) on its
     * group {@code g}. Refused, saying why, when the instance is not a fixed cycle: durations,
     * angles, phase, offset and period must be constants, no state may have an exit condition
     * or a profile other than linear, and {@code start} and {@code cycles} must not be written.
     */
    public static Table expand(Program p, Instance in, Group g) {
        Automaton a = in.automaton();
        refuseUnlessRepeating(in);
        int n = a.states().size();
        double[] t = new double[n];
        double sum = 0;
        for (int i = 0; i < n; i++) {
            Timing ti = a.times().get(i);
            if (ti.exit() != null) {
                throw new EditRefused(EditMsg.STATE_HAS_EXIT, i, a.name());
            }
            t[i] = constant(ti.duration(), Message.of(EditMsg.DURATION_OF_STATE, i));
            sum += t[i];
        }
        double period = in.period() == null ? sum : constant(in.period(), "period");
        double phase = in.phase() == null ? 0 : constant(in.phase(), "phase");
        double offset = in.offset() == null ? 0 : constant(in.offset(), "offset");
        double[] start = new double[n + 1];
        for (int i = 0; i < n; i++) {
            start[i + 1] = start[i] + t[i] / sum;
        }
        int m = g.size();
        double[] u = new double[m];
        TreeSet<Double> cuts = new TreeSet<>(List.of(0.0, 1.0));
        for (int k = 0; k < m; k++) {
            u[k] = frac(-(offset + k * phase));
            for (int i = 0; i < n; i++) {
                double x = frac(start[i] - u[k]);
                if (cuts.subSet(x - SAME, x + SAME).isEmpty() && 1 - x > SAME) {
                    cuts.add(x);
                }
            }
        }
        double[][] targets = targets(a, m);
        List<Double> xs = new ArrayList<>(cuts);
        List<double[]> rows = new ArrayList<>();
        double[] seconds = new double[xs.size() - 1];
        for (int r = 0; r + 1 < xs.size(); r++) {
            double mid = (xs.get(r) + xs.get(r + 1)) / 2;
            double end = xs.get(r + 1);
            double[] row = new double[m];
            for (int k = 0; k < m; k++) {
                int i = stateAt(start, frac(u[k] + mid));
                double into = u[k] + end - start[i];
                into -= Math.floor(into);
                double q = into < SAME ? 1 : Math.min(1, into / (start[i + 1] - start[i]));
                double from = targets[(i + n - 1) % n][k];
                row[k] = from + (targets[i][k] - from) * q;
            }
            rows.add(row);
            seconds[r] = (end - xs.get(r)) * period;
        }
        return new Table(rows, seconds);
    }

    /**
     * Refuses a gait table, and an instance that does not repeat as a table does. Every attribute
     * of an instance is read by {@link #expand} or refused here: a new attribute of
     * {@link Instance} does not compile until this copy says which (issue 32, trial changes).
     */
    private static void refuseUnlessRepeating(Instance in) {
        Automaton a = in.automaton();
        if (a.table()) {
            throw new EditRefused(EditMsg.ALREADY_TABLE, a.name());
        }
        Instance repeating = new Instance(a, in.group(), in.on(), in.phase(), in.offset(), in.period(), null, null, in.pos());
        if (!repeating.equals(in)) {
            throw new EditRefused(EditMsg.NOT_REPEATING);
        }
    }

    /**
     * Writes the expansion of {@code in} into {@code text}: table {@code name} after the last
     * automaton, and the instance plays it (its element renamed, its {@code phase} and
     * {@code offset} set to 0 where written; its {@code period} stays, the table's times add up
     * to it).
     */
    public static TextEdit write(String text, Program p, Instance in, Group g, String name) {
        Table t = expand(p, in, g);
        var s = ScriptEdits.span(in.pos());
        List<Replacement> edits = new ArrayList<>(PaletteEdits.addGaitTable(text, p, name, t.rowTexts(), t.times())
                .replacements());
        edits.addAll(ScriptEdits.rename(text, s, in.name(), ElementWriter.name(name, "gait table")));
        for (String attr : List.of("phase", "offset")) {
            if (s.value(attr) != null) {
                edits.addAll(ScriptEdits.setAttribute(text, in.pos(), attr, "0").replacements());
            }
        }
        return new TextEdit(edits);
    }

    /**
     * "Make phase automaton", the way back: when every column of gait table {@code table} (on a
     * group of {@code m} modules) is column 0 shifted down by the same number {@code s} of rows
     * per module, and the rows last equally long (so that {@code s} rows are a constant part of
     * the cycle), the table is a phase automaton: column 0's rows as states, phase {@code s/R}.
     * Refused, saying why, otherwise.
     *
     * @return column 0's angles and each row's seconds, and the phase
     */
    public static Cycle cycleOf(Automaton table, int m) {
        if (!table.table()) {
            throw new EditRefused(EditMsg.NOT_A_TABLE, table.name());
        }
        int rows = table.states().size();
        double[][] cell = targets(table, m);
        double[] seconds = new double[rows];
        for (int r = 0; r < rows; r++) {
            if (table.times().get(r).exit() != null) {
                throw new EditRefused(EditMsg.ROW_HAS_EXIT, r, table.name());
            }
            seconds[r] = constant(table.times().get(r).duration(), Message.of(EditMsg.DURATION_OF_ROW, r));
        }
        for (int shift = 0; shift < rows; shift++) {
            if (shifted(cell, shift, m) && (shift == 0 || equal(seconds))) {
                double[] column = new double[rows];
                for (int r = 0; r < rows; r++) {
                    column[r] = cell[r][0];
                }
                return new Cycle(column, seconds, (double) shift / rows);
            }
        }
        throw new EditRefused(EditMsg.NOT_SHIFTED, table.name());
    }

    /**
     * Writes "Make phase automaton" for instance {@code in} of a gait table on group {@code g}:
     * phase automaton {@code name} after the last automaton, one state per distinct angle of
     * the table's first column ({@code name_0}, {@code name_1}, …, after the last state, or in a
     * new {@code <states>} after {@code <automata>}), and the instance plays it (its element
     * renamed, its {@code phase} set; offset and period stay).
     */
    public static TextEdit writeCycle(String text, Program p, Instance in, Group g, String name) {
        Automaton table = in.automaton();
        Cycle c = cycleOf(table, g.size());
        ElementWriter.name(name, "automaton");
        List<Double> values = new ArrayList<>();
        List<String> states = new ArrayList<>();
        for (double v : c.angles()) {
            if (!values.contains(v)) {
                values.add(v);
            }
            states.add(name + "_" + values.indexOf(v));
        }
        StringBuilder times = new StringBuilder();
        for (double t : c.seconds()) {
            times.append(times.length() == 0 ? "" : ", ").append(Numbers.format(t));
        }
        List<Replacement> edits = new ArrayList<>(PaletteEdits.addAutomaton(text, p, name, String.join(", ", states),
                times.toString()).replacements());
        var last = ScriptEdits.span(table.pos());
        String indent = ElementWriter.indent(text, last.start());
        StringBuilder poses = new StringBuilder();
        boolean fresh = p.states().stream().noneMatch(d -> d.pos().span() != null && d.pos().file().equals(p.file()));
        String inner = fresh ? indent : ElementWriter.indent(text, p.states().get(p.states().size() - 1).pos().span().start());
        for (int i = 0; i < values.size(); i++) {
            poses.append('\n').append(inner).append(ElementWriter.tag(name + "_" + i)
                    .attr("angles", Numbers.format(values.get(i))).empty());
        }
        if (fresh) {
            SourceSpan automata = SectionEdits.sectionAt(text, p.file(), "automata", last.start());
            String outer = indent.length() >= 2 ? indent.substring(2) : "";
            edits.add(new Replacement(automata.end(), 0, "\n" + outer + ElementWriter.tag("states").open() + poses
                    + "\n" + outer + ElementWriter.close("states")));
        } else {
            edits.add(new Replacement(p.states().get(p.states().size() - 1).pos().span().end(), 0, poses.toString()));
        }
        edits.addAll(ScriptEdits.rename(text, ScriptEdits.span(in.pos()), in.name(), name));
        edits.addAll(ScriptEdits.setAttribute(text, in.pos(), "phase", Numbers.format(c.phase())).replacements());
        return new TextEdit(edits);
    }

    /**
     * A phase automaton's cycle.
     *
     * @param angles  each state's angle (for every module)
     * @param seconds each state's duration
     * @param phase   the phase between neighbouring modules, in cycles
     */
    public record Cycle(double[] angles, double[] seconds, double phase) {
    }

    private static boolean shifted(double[][] cell, int shift, int m) {
        int rows = cell.length;
        for (int k = 0; k < m; k++) {
            for (int r = 0; r < rows; r++) {
                int from = Math.floorMod(r - k * shift, rows);
                if (Math.abs(cell[r][k] - cell[from][0]) > 1e-9) {
                    return false;
                }
            }
        }
        return true;
    }

    private static boolean equal(double[] v) {
        for (double x : v) {
            if (Math.abs(x - v[0]) > 1e-9) {
                return false;
            }
        }
        return true;
    }

    /** Each state's target per module position. */
    private static double[][] targets(Automaton a, int m) {
        double[][] out = new double[a.states().size()][m];
        for (int i = 0; i < out.length; i++) {
            StateDef s = a.states().get(i);
            if (s.interp() != Interp.LINEAR) {
                throw new EditRefused(EditMsg.NOT_LINEAR, s.name(), s.interp());
            }
            if (s.angles().size() != 1 && s.angles().size() != m) {
                throw new EditRefused(EditMsg.ANGLE_COUNT, s.name(), s.angles().size(), m);
            }
            for (int k = 0; k < m; k++) {
                out[i][k] = constant(s.angles().get(s.angles().size() == 1 ? 0 : k),
                        Message.of(EditMsg.ANGLE_OF_STATE, s.name()));
            }
        }
        return out;
    }

    private static int stateAt(double[] start, double u) {
        int i = 0;
        while (i + 2 < start.length && u >= start[i + 1]) {
            i++;
        }
        return i;
    }

    /**
     * The value of {@code e}, refused when it is known only while running; {@code what} names it
     * (a message, or an attribute's name).
     */
    private static double constant(Expression e, Object what) {
        double v = Diagrams.constant(e);
        if (Double.isNaN(v)) {
            throw new EditRefused(EditMsg.NOT_CONSTANT, what, e.text());
        }
        return v;
    }

    private static double frac(double x) {
        return x - Math.floor(x);
    }
}
