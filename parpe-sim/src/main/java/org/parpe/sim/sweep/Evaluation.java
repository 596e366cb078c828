package org.parpe.sim.sweep;

/**
 * One simulation made by an {@link Optimizer}.
 *
 * @param start    which of the independent searches made it, 0-based
 * @param number   its number within that search, 0-based
 * @param row      the run and its measurements ({@link Point#index()} is {@link #number})
 * @param score    the objective, or NaN when the run failed
 * @param feasible whether the run met the constraints
 */
public record Evaluation(int start, int number, SweepRow row, double score, boolean feasible) {
}
