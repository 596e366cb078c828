package org.parpe.core.model;

import org.parpe.core.diag.SourcePos;
import org.parpe.core.lang.Numbers;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/**
 * A run-time parameter (PARSL.md §3).
 *
 * @param name  the name
 * @param value the default value
 * @param min   inclusive lower bound, or {@code null}
 * @param max   inclusive upper bound, or {@code null}
 * @param label the label for the parameters dialog, or empty
 * @param pos   the element
 */
public record Parameter(String name, double value, Double min, Double max, String label,
                        SourcePos pos) {

    /** The label to show a user: the label if given, else the name. */
    public String displayLabel() {
        return label.isEmpty() ? name : label;
    }

    /** An error message if {@code v} is not allowed, else {@code null}. */
    public String check(double v) {
        Message m = problem(v);
        return m == null ? null : m.toString();
    }

    /** What is wrong with {@code v} for this parameter, or {@code null} if it is allowed. */
    public Message problem(double v) {
        if (!Double.isFinite(v)) {
            return Message.of(Msg.PARAMETER_NOT_FINITE, name, v);
        }
        if (min != null && v < min) {
            return Message.of(Msg.PARAMETER_BELOW_MIN, name, Numbers.format(min), Numbers.format(v));
        }
        if (max != null && v > max) {
            return Message.of(Msg.PARAMETER_ABOVE_MAX, name, Numbers.format(max), Numbers.format(v));
        }
        return null;
    }
}
