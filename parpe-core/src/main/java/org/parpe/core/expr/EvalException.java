package org.parpe.core.expr;

/**
 * A run-time evaluation failure (a non-finite value). Thrown by nodes; the scheduler adds the
 * expression's place and the tick time before reporting it.
 */
public final class EvalException extends RuntimeException {
    /** Creates the exception with a short description of what went wrong. */
    public EvalException(String message) {
        super(message, null, false, false);
    }
}
