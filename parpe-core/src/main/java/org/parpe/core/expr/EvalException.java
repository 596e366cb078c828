package org.parpe.core.expr;

/**
 * A run-time evaluation failure (a non-finite value). Thrown by nodes; the scheduler adds the
 * expression's place and the tick time before reporting it.
 */
public final class EvalException extends RuntimeException {
    private final transient org.parpe.core.text.Message text;

    /** Creates the exception with a short description of what went wrong: {@code key} with {@code args}. */
    public EvalException(org.parpe.core.text.Msg key, Object... args) {
        super(null, null, false, false);
        this.text = org.parpe.core.text.Message.of(key, args);
    }

    /** What went wrong, to be shown in the chosen language. */
    public org.parpe.core.text.Message text() {
        return text;
    }

    @Override
    public String getMessage() {
        return text.toString();
    }
}
