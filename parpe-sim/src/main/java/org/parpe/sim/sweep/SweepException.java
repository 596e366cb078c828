package org.parpe.sim.sweep;

import org.parpe.core.text.Key;
import org.parpe.core.text.Message;

/**
 * A sweep or optimisation that cannot start: a bad {@code --vary} specification, an unknown
 * parameter, a value outside a parameter's bounds, a script that does not load, shards that
 * cannot be merged. It carries one line meant for the user as a {@link Message} (key and
 * arguments), shown in the chosen language when it is shown (one line per shard for an
 * {@link IncompleteSweepException}).
 */
public class SweepException extends Exception {
    private static final long serialVersionUID = 1L;

    private final transient Message text;

    /** An exception whose line for the user is {@code text}. */
    public SweepException(Message text) {
        super(null, null);
        this.text = text;
    }

    /** An exception whose line for the user is {@code key} with {@code args}. */
    public SweepException(Key key, Object... args) {
        this(Message.of(key, args));
    }

    /**
     * An exception with a line already in the user's words, shown as it is ({@link Message#verbatim}):
     * the IDE's sweep panels' and the command line's own refusals, from their bundles.
     */
    public SweepException(String message) {
        this(Message.verbatim(message));
    }

    /** The line for the user, with its key and arguments. */
    public Message text() {
        return text;
    }

    /** The line for the user in the chosen language. */
    @Override
    public String getMessage() {
        return text.toString();
    }
}
