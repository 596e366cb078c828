package org.parpe.sim.sweep;

/**
 * A sweep or optimisation that cannot start: a bad {@code --vary} specification, an unknown
 * parameter, a value outside a parameter's bounds, a script that does not load, shards that
 * cannot be merged. The message is one line meant for the user (one line per shard for an
 * {@link IncompleteSweepException}).
 */
public class SweepException extends Exception {
    private static final long serialVersionUID = 1L;

    /** An exception with a one-line message for the user. */
    public SweepException(String message) {
        super(message);
    }
}
