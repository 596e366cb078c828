package org.parpe.core.run;

/**
 * Decides when each tick of a {@link Run} happens in wall-clock time. The run itself is
 * deterministic whatever the pacing: a pacer only waits. The caller supplies it: as fast as
 * possible ({@link #NONE}) for headless runs and tests, or a {@link WallClockPacer} for
 * hardware, real-time simulation and the IDE's speeds and pause.
 */
@FunctionalInterface
public interface Pacer {

    /** Never waits: the run goes as fast as the machine allows. */
    Pacer NONE = (run, time) -> { };

    /**
     * Called before the tick at simulated time {@code time}; may wait (sleep, pause). Must
     * return promptly once {@code run.stopRequested()} is true.
     *
     * @throws InterruptedException when the waiting thread is interrupted (the run stops)
     */
    void beforeTick(Run run, double time) throws InterruptedException;
}
