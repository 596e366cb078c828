package org.parpe.gui.run;

import org.parpe.core.text.Key;
import org.parpe.gui.text.UiMsg;

/** How fast simulated time runs compared with the wall clock. */
public enum Speed {
    REAL_TIME(UiMsg.SPEED_REAL_TIME, 1),
    TIMES_2(UiMsg.SPEED_TIMES_2, 2),
    TIMES_10(UiMsg.SPEED_TIMES_10, 10),
    MAX(UiMsg.SPEED_MAX, Double.POSITIVE_INFINITY);

    private final Key label;
    private final double factor;

    Speed(Key label, double factor) {
        this.label = label;
        this.factor = factor;
    }

    /** The text shown in the tool bar. */
    public String label() {
        return label.text();
    }

    /** Simulated seconds per wall-clock second (infinite: unpaced). */
    public double factor() {
        return factor;
    }
}
