package org.parpe.core.run;

/**
 * Receives the commanded joint angles of every tick (step 4 of PARSL.md §11). Trace writer,
 * simulator, serial bus and GUI plots are all sinks. A plant (simulator) advances its own
 * state by one tick in {@link #accept} so that the next tick's sensor reading sees the result.
 * Sinks are called on the engine thread; the array is reused and must be copied if kept.
 */
public interface JointSink {

    /** Called once before tick 0. */
    default void start(RunInfo info) {
    }

    /**
     * The setpoints of tick {@code tick} at time {@code time}, degrees, one per module in
     * ascending ID order.
     */
    void accept(long tick, double time, double[] commanded);

    /** Called once when the run ends, whatever the reason. */
    default void finish(RunOutcome outcome) {
    }
}
