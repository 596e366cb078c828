package org.parpe.core.run;

/**
 * How a run ended.
 *
 * @param status  completed (main ended or duration reached), stopped by the user, or failed
 * @param time    simulated time of the last emitted tick
 * @param message for {@link Status#ERROR} the located message, else empty
 */
public record RunOutcome(Status status, double time, String message) {

    /** The kinds of ending. */
    public enum Status { COMPLETED, STOPPED, ERROR }
}
