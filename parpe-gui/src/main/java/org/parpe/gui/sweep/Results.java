package org.parpe.gui.sweep;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.lang.Numbers;
import org.parpe.sim.sweep.Constraints;
import java.util.function.Predicate;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.SweepResult;
import org.parpe.sim.sweep.SweepRow;

/**
 * The rows of one sweep or optimisation as the dialog shows them, in the engine's order
 * (combination order for a sweep, evaluation order for an optimisation). UI thread only.
 */
final class Results {
    /** Whether rows come from a sweep or from an optimisation. */
    enum Mode { SWEEP, OPTIMISE }

    private final Path script;
    private final Mode mode;
    private final List<String> parameters;
    private final Objective objective;
    private final Constraints constraints;
    private final Map<String, Double> own;
    private final List<SweepRow> rows = new ArrayList<>();

    /** {@code own}: the script's own values of {@code parameters} (its {@code value}s), to tell a best run that is only them. */
    Results(Path script, Mode mode, List<String> parameters, Map<String, Double> own, Objective objective, Constraints constraints) {
        this.script = script;
        this.mode = mode;
        this.parameters = List.copyOf(parameters);
        this.own = Map.copyOf(own);
        this.objective = objective;
        this.constraints = constraints;
    }

    /** The path of the script the runs were made with. */
    Path script() {
        return script;
    }

    Mode mode() {
        return mode;
    }

    /** The varied (or searched) parameters, in the order of the table's columns. */
    List<String> parameters() {
        return parameters;
    }

    Objective objective() {
        return objective;
    }

    Constraints constraints() {
        return constraints;
    }

    List<SweepRow> rows() {
        return rows;
    }

    void add(SweepRow row) {
        rows.add(row);
    }

    /** Replaces the rows with the engine's final list (the same runs, in its order). */
    void replace(List<SweepRow> all) {
        rows.clear();
        rows.addAll(all);
    }

    /**
     * The rule of "best": a sweep's is {@code parpe sweep}'s ({@link SweepResult#STANDING}: a run
     * whose robot fell over never counts); an optimisation's is its constraints.
     */
    private Predicate<SweepRow> rule() {
        return mode == Mode.SWEEP ? SweepResult.STANDING : r -> constraints.violation(r) == 0;
    }

    /** Whether {@code row} may be the best: it ran without error, has a measurement and meets {@link #rule}. */
    boolean acceptable(SweepRow row) {
        return SweepResult.contender(row, objective, rule());
    }

    /** The acceptable row with the highest objective, the earliest among equals, or null. */
    SweepRow best() {
        return SweepResult.best(rows, objective, rule()).orElse(null);
    }

    /**
     * The number of {@code row} in the engine's order, from 0 as {@code parpe sweep}'s {@code run}
     * column counts (-1 when it is not one of these rows).
     */
    int number(SweepRow row) {
        for (int i = 0; i < rows.size(); i++) {
            if (rows.get(i) == row) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Whether {@code row} ran with the script's own values of every varied parameter (an
     * optimisation starts there): then nothing the sweep tried beat the script as it is.
     */
    boolean scriptsOwn(SweepRow row) {
        if (parameters.isEmpty()) {
            return false;
        }
        for (String p : parameters) {
            Double v = row.values().get(p);
            Double o = own.get(p);
            if (v == null || o == null || Math.abs(v - o) > 1e-9 * Math.max(1, Math.abs(o))) {
                return false;
            }
        }
        return true;
    }

    /** The sentence that names the best row {@code best} after a finished or stopped sweep. */
    String bestSentence(SweepRow best) {
        String measured = objective.label() + " " + ResultsTable.number(objective.of(best)) + (best.fell() ? " (its robot fell over)" : "");
        return scriptsOwn(best)
                ? "Nothing beat the script's own values: the best is run " + number(best) + " with them (" + describe(best.values()) + "): " + measured
                        + ". Widen the ranges or try other parameters."
                : "Best: run " + number(best) + ", " + describe(best.values()) + ": " + measured;
    }

    /** The parameter values of the best row, or an empty map. */
    Map<String, Double> bestValues() {
        SweepRow b = best();
        return b == null ? Map.of() : new LinkedHashMap<>(b.values());
    }

    /** {@code values} as {@code name = value, ...}. */
    static String describe(Map<String, Double> values) {
        StringBuilder b = new StringBuilder();
        values.forEach((k, v) -> b.append(b.length() == 0 ? "" : ", ").append(k).append(" = ").append(Numbers.format(v)));
        return b.toString();
    }
}
