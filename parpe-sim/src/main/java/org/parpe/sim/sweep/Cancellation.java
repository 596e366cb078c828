package org.parpe.sim.sweep;

import java.util.concurrent.atomic.AtomicBoolean;

/**
 * The one flag that stops a sweep or an optimisation: a Stop button or an interrupt handler
 * calls {@link #cancel()} from any thread; the simulations in progress end at their next tick
 * and no new one starts.
 */
public class Cancellation {
    private final AtomicBoolean cancelled = new AtomicBoolean();

    /** Asks the work to stop; safe from any thread. */
    public void cancel() {
        cancelled.set(true);
    }

    /** Whether {@link #cancel()} was called. */
    public boolean cancelled() {
        return cancelled.get();
    }
}
