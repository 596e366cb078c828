package org.parpe.gui.run;

/** How fast simulated time runs compared with the wall clock. */
public enum Speed {
    REAL_TIME("Real time", 1),
    TIMES_2("\u00d72", 2),
    TIMES_10("\u00d710", 10),
    MAX("As fast as possible", Double.POSITIVE_INFINITY);

    private final String label;
    private final double factor;

    Speed(String label, double factor) {
        this.label = label;
        this.factor = factor;
    }

    /** The text shown in the tool bar. */
    public String label() {
        return label;
    }

    /** Simulated seconds per wall-clock second (infinite: unpaced). */
    public double factor() {
        return factor;
    }
}
