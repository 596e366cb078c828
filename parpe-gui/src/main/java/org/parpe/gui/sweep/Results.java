package org.parpe.gui.sweep;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.lang.Numbers;
import org.parpe.sim.sweep.Constraints;
import org.parpe.sim.sweep.Objective;
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
    private final List<SweepRow> rows = new ArrayList<>();

    Results(Path script, Mode mode, List<String> parameters, Objective objective, Constraints constraints) {
        this.script = script;
        this.mode = mode;
        this.parameters = List.copyOf(parameters);
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

    /** Whether {@code row} counts for "best": it ran without error and, when optimising, met the constraints. */
    boolean acceptable(SweepRow row) {
        return row.ok() && !Double.isNaN(objective.of(row))
                && (mode == Mode.SWEEP || constraints.violation(row) == 0);
    }

    /** The acceptable row with the highest objective, the earliest among equals, or null. */
    SweepRow best() {
        SweepRow best = null;
        for (SweepRow r : rows) {
            if (acceptable(r) && (best == null || objective.of(r) > objective.of(best))) {
                best = r;
            }
        }
        return best;
    }

    /** The number of {@code row} in the engine's order, from 1 (0 when it is not one of these rows). */
    int number(SweepRow row) {
        for (int i = 0; i < rows.size(); i++) {
            if (rows.get(i) == row) {
                return i + 1;
            }
        }
        return 0;
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
