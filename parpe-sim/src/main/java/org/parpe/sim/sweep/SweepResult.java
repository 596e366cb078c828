package org.parpe.sim.sweep;

import java.util.Comparator;
import java.util.List;
import java.util.Optional;

/**
 * What a sweep gave.
 *
 * @param rows      the finished runs in combination order (all of them unless cancelled)
 * @param cancelled whether the sweep was cancelled before every run was done
 */
public record SweepResult(List<SweepRow> rows, boolean cancelled) {

    public SweepResult {
        rows = List.copyOf(rows);
    }

    /** The run without an error that scored best on {@code objective}, if any (the first among equals). */
    public Optional<SweepRow> best(Objective objective) {
        return rows.stream().filter(r -> r.ok() && !Double.isNaN(objective.of(r)))
                .max(Comparator.comparingDouble(objective::of).thenComparing(r -> -r.point().index()));
    }
}
