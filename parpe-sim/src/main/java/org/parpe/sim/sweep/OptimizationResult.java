package org.parpe.sim.sweep;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;

/**
 * What an optimisation found.
 *
 * @param objective the objective maximised
 * @param starts    the evaluations of each independent search, in the order made
 * @param cancelled whether it was cancelled before the budget was spent
 */
public record OptimizationResult(Objective objective, List<List<Evaluation>> starts, boolean cancelled) {

    public OptimizationResult {
        starts = starts.stream().map(List::copyOf).toList();
    }

    /** Every evaluation, interleaved as if the searches had advanced in step (start 0, 1, ..., then 0 again). */
    public List<Evaluation> evaluations() {
        List<Evaluation> all = new ArrayList<>();
        int longest = starts.stream().mapToInt(List::size).max().orElse(0);
        for (int n = 0; n < longest; n++) {
            for (List<Evaluation> s : starts) {
                if (n < s.size()) {
                    all.add(s.get(n));
                }
            }
        }
        return all;
    }

    /** The feasible evaluation with the highest score (the earliest among equals), if any. */
    public Optional<Evaluation> best() {
        List<Evaluation> all = evaluations();
        Evaluation best = null;
        for (Evaluation e : all) {
            if (e.feasible() && !Double.isNaN(e.score()) && (best == null || e.score() > best.score())) {
                best = e;
            }
        }
        return Optional.ofNullable(best);
    }

    /** The best run whether or not it met the constraints (to explain an optimisation that found none). */
    public Optional<Evaluation> bestIgnoringConstraints() {
        return evaluations().stream().filter(e -> !Double.isNaN(e.score()))
                .max(Comparator.comparingDouble(Evaluation::score));
    }

    /**
     * The convergence curve: for each evaluation of {@link #evaluations()}, the best feasible
     * score so far (NaN until there is one).
     */
    public double[] bestSoFar() {
        List<Evaluation> all = evaluations();
        double[] curve = new double[all.size()];
        double best = Double.NaN;
        for (int i = 0; i < curve.length; i++) {
            Evaluation e = all.get(i);
            if (e.feasible() && !Double.isNaN(e.score()) && (Double.isNaN(best) || e.score() > best)) {
                best = e.score();
            }
            curve[i] = best;
        }
        return curve;
    }
}
