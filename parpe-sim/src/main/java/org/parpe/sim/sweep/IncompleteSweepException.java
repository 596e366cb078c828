package org.parpe.sim.sweep;

import java.util.List;

/**
 * Shards that cannot be merged yet because some of them are missing or unfinished: the message
 * has one line per such shard, and {@link #rerun()} says which shards to run again.
 */
public final class IncompleteSweepException extends SweepException {
    private static final long serialVersionUID = 1L;

    private final transient List<Integer> rerun;
    private final int of;

    /** Shards {@code rerun} (numbered from 1) of a split into {@code of} are missing or unfinished. */
    public IncompleteSweepException(String message, List<Integer> rerun, int of) {
        super(message);
        this.rerun = List.copyOf(rerun);
        this.of = of;
    }

    /** The shards to run again, in order. */
    public List<Integer> rerun() {
        return rerun;
    }

    /** Into how many shards the sweep was split. */
    public int of() {
        return of;
    }
}
