package org.parpe.core.plot;

/**
 * The one style of every plot (PNG and IDE): colours as 0xRRGGBB, and how commanded and
 * measured angles are told apart. Commanded is dashed (a plan), measured is solid (what
 * happened), in the module's colour both.
 */
public final class PlotStyle {
    /** The colours of the modules' curves, in the order the modules are shown. */
    private static final int[] SERIES = {0x1F77B4, 0xD62728, 0x2CA02C, 0x9467BD, 0xFF7F0E, 0x17BECF, 0x8C564B, 0xE377C2};

    /** The line through the best run at each value of a sweep. */
    public static final int BEST = 0x1F77B4;
    /** The line of an optimisation's best acceptable objective so far. */
    public static final int BEST_SO_FAR = 0xD62728;
    /** A run whose robot fell over or failed: a hollow ring, never the best. */
    public static final int FELL = 0xD62728;
    /** An evaluation that misses a constraint. */
    public static final int MISSES = 0xFF7F0E;
    /** A run that counts (a sweep's run, an evaluation that meets the constraints), behind the best line. */
    public static final int OTHER_RUN = 0xA0A0A0;

    /** Width of a curve, in points at normal size. */
    public static final float LINE_WIDTH = 2f;
    /** Dash and gap lengths of a commanded curve, in points at normal size. */
    private static final float[] DASH = {6f, 4f};

    /** The legend's names of the two curves of a module. */
    public static final String COMMANDED = "commanded";
    public static final String MEASURED = "measured";

    private PlotStyle() {
    }

    /** The colour of the {@code k}th module shown. */
    public static int series(int k) {
        return SERIES[Math.floorMod(k, SERIES.length)];
    }

    /** Whether the curve is dashed: commanded yes, measured no. */
    public static boolean dashed(boolean commanded) {
        return commanded;
    }

    /** The dash pattern of a commanded curve scaled by {@code scale} (a copy). */
    public static float[] dash(float scale) {
        return new float[] {DASH[0] * scale, DASH[1] * scale};
    }
}
