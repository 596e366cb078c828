package org.parpe.core.model;

/** Motion profile into a state (PARSL.md §5). */
public enum Interp {
    /** Straight line in joint space. */
    LINEAR,
    /** Jump to the target at once and hold. */
    STEP,
    /** Cosine ease-in/ease-out. */
    SMOOTH;

    /** The profile value for progress {@code q} in [0, 1]. */
    public double shape(double q) {
        switch (this) {
            case STEP:
                return 1.0;
            case SMOOTH:
                return (1.0 - Math.cos(Math.PI * q)) / 2.0;
            default:
                return q;
        }
    }

    /** The name used in scripts. */
    public String word() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
