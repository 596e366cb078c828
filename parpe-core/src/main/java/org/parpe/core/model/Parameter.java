package org.parpe.core.model;

import org.parpe.core.diag.SourcePos;
import org.parpe.core.lang.Numbers;

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
        if (!Double.isFinite(v)) {
            return "parameter '" + name + "' must be a finite number, got " + v;
        }
        if (min != null && v < min) {
            return "parameter '" + name + "' must be >= " + Numbers.format(min) + ", got " + Numbers.format(v);
        }
        if (max != null && v > max) {
            return "parameter '" + name + "' must be <= " + Numbers.format(max) + ", got " + Numbers.format(v);
        }
        return null;
    }
}
