package org.parpe.sim.sweep;

/**
 * Makes single runs of one sweep's script, robot and duration. A worker thread talks to the copy
 * of the simulator in its {@link Lanes lane} through this interface, which (like {@link RunSetup},
 * {@link Point}, {@link SweepRow} and {@link Cancellation}) is the same class on both sides.
 */
public interface PointRunner {
    /**
     * Runs {@code point} on a fresh robot until the duration, a run-time error, or
     * {@code cancellation}; returns {@code null} when cancelled before the end.
     */
    SweepRow run(Point point, Cancellation cancellation);
}
