package org.parpe.sim.build;

import org.parpe.core.edit.TextEdit;

/**
 * One builder edit of a robot configuration's text, or the reason it cannot be made. A builder
 * hands {@link #edit} to the editor as one Undo step labelled {@link #description}; a refused
 * edit has no text edit and says why in {@link #refusal} ("the kit has no foot left").
 *
 * @param edit        the change of the draft's text (through {@code org.parpe.core.edit}), or null when refused
 * @param description one line for the Undo menu ("Add segment s3 on body.2"), or null when refused
 * @param refusal     why the edit cannot be made, or null when it can
 */
public record BuildEdit(TextEdit edit, String description, String refusal) {

    public BuildEdit {
        if ((refusal == null) == (edit == null)) {
            throw new IllegalArgumentException("a build edit has a text edit or a refusal, not both or neither");
        }
    }

    /** An edit that can be made. */
    public static BuildEdit of(TextEdit edit, String description) {
        return new BuildEdit(edit, description, null);
    }

    /** An edit refused, saying why. */
    public static BuildEdit refuse(String why) {
        return new BuildEdit(null, null, why);
    }

    /** Whether the edit cannot be made ({@link #refusal} says why). */
    public boolean refused() {
        return refusal != null;
    }
}
