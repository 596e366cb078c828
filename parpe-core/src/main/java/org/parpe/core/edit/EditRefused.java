package org.parpe.core.edit;

import org.parpe.core.text.EditMsg;
import org.parpe.core.text.Message;

/**
 * An edit that cannot be written, saying why: a key of {@link EditMsg} with its arguments,
 * formatted in the chosen language only when it is shown (the IDE shows {@link #getMessage()}
 * under the diagram or grid in its language). An {@link IllegalArgumentException}, as the
 * refused value is an argument of the edit.
 */
public final class EditRefused extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    private final transient Message text;

    /** The refusal {@code key} with {@code args}. */
    public EditRefused(EditMsg key, Object... args) {
        super(null, null);
        this.text = Message.of(key, args);
    }

    /** Why the edit is refused, to be shown in the chosen language. */
    public Message text() {
        return text;
    }

    @Override
    public String getMessage() {
        return text.toString();
    }
}
