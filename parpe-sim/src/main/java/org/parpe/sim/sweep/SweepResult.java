package org.parpe.sim.sweep;

import java.util.List;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * What a sweep gave.
 *
 * @param rows      the finished runs in combination order (all of them unless cancelled)
 * @param cancelled whether the sweep was cancelled before every run was done
 */
public record SweepResult(List<SweepRow> rows, boolean cancelled) {

    /** The default rule of "best" for a sweep: a run whose robot fell over is never the best gait. */
    public static final Predicate<SweepRow> STANDING = r -> !r.fell();
    /** The rule when the user lets fallen runs count ({@code --count-fallen}). */
    public static final Predicate<SweepRow> ANY = r -> true;

    /** {@link #ANY} when fallen runs count, else the default {@link #STANDING}. */
    public static Predicate<SweepRow> rule(boolean fallenCount) {
        return fallenCount ? ANY : STANDING;
    }

    public SweepResult {
        rows = List.copyOf(rows);
    }

    /** The best run by the default rule ({@link #STANDING}), if any: see {@link #best(List, Objective, Predicate)}. */
    public Optional<SweepRow> best(Objective objective) {
        return best(rows, objective, STANDING);
    }

    /**
     * Whether {@code row} may be the best on {@code objective}: it ran without an error, has a
     * measurement, and meets {@code rule} ({@link #STANDING} unless the user let fallen runs count).
     */
    public static boolean contender(SweepRow row, Objective objective, Predicate<SweepRow> rule) {
        return row.ok() && !Double.isNaN(objective.of(row)) && rule.test(row);
    }

    /**
     * The {@link #contender contending} run of {@code rows} that scored best on {@code objective},
     * the first in {@code rows}' order among equals. The one rule of {@code parpe sweep}'s summary
     * and plot and the IDE's Best and Apply best.
     */
    public static Optional<SweepRow> best(List<SweepRow> rows, Objective objective, Predicate<SweepRow> rule) {
        SweepRow best = null;
        for (SweepRow r : rows) {
            if (contender(r, objective, rule) && (best == null || objective.of(r) > objective.of(best))) {
                best = r;
            }
        }
        return Optional.ofNullable(best);
    }
}
