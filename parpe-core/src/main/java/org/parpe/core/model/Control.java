package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * A live input (PARSL.md §4).
 *
 * @param name  the name, referenced as {@code $name}
 * @param type  slider, text or radio
 * @param value the initial value (for a radio: the symbol code of the initial word)
 * @param min   slider minimum, else {@code null}
 * @param max   slider maximum, else {@code null}
 * @param step  slider step, or {@code null}
 * @param label label, or empty
 * @param words radio option words in order, else empty
 * @param keys  key bindings (slider: increase, decrease; radio: one per word), or empty
 * @param pos   the element
 */
public record Control(String name, ControlType type, double value, Double min, Double max,
                      Double step, String label, List<String> words, List<String> keys,
                      SourcePos pos) {

    public Control {
        words = List.copyOf(words);
        keys = List.copyOf(keys);
    }

    /** The label to show a user: the label if given, else the name. */
    public String displayLabel() {
        return label.isEmpty() ? name : label;
    }

    /** The kinds of control. */
    public enum ControlType {
        SLIDER, TEXT, RADIO;

        /** The name used in scripts. */
        public String word() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }
}
