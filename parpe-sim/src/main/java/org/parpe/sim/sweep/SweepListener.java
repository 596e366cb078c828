package org.parpe.sim.sweep;

/**
 * Follows a sweep or an optimisation. Called from the worker threads, one call at a time (a
 * GUI must hand the data over to its UI thread, e.g. with {@code Display.asyncExec}).
 */
public interface SweepListener {

    /** Nothing to follow. */
    SweepListener NONE = new SweepListener() {
    };

    /** {@code done} of {@code total} runs have finished (in any order). */
    default void progress(int done, int total) {
    }

    /**
     * The next row in combination order (sweeps), or the next evaluation as it finishes
     * (optimisation): rows can be written out as they come.
     */
    default void row(SweepRow row) {
    }
}
