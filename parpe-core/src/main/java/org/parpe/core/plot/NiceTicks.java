package org.parpe.core.plot;

import java.util.Locale;

/**
 * The one choice of round tick values for every chart the IDE draws: a step of 1, 2 or 5 ×
 * 10^k giving about the asked number of intervals, and the multiples of it within a range.
 */
public final class NiceTicks {
    private static final int MAX_TICKS = 50;

    private NiceTicks() {
    }

    /** A step of 1, 2 or 5 × 10^k giving about {@code intervals} intervals over {@code span} (> 0). */
    public static double step(double span, int intervals) {
        double raw = span / Math.max(1, intervals);
        double mag = Math.pow(10, Math.floor(Math.log10(raw)));
        double n = raw / mag;
        return (n < 1.5 ? 1 : n < 3.5 ? 2 : n < 7.5 ? 5 : 10) * mag;
    }

    /** The multiples of {@link #step} within {@code [lo, hi]}, ascending (none for an empty or bad range). */
    public static double[] within(double lo, double hi, int intervals) {
        if (!(hi > lo) || !Double.isFinite(lo) || !Double.isFinite(hi)) {
            return new double[0];
        }
        double step = step(hi - lo, intervals);
        long first = (long) Math.ceil(lo / step - 1e-9);
        long last = (long) Math.floor(hi / step + 1e-9);
        int n = (int) Math.max(0, Math.min(MAX_TICKS, last - first + 1));
        double[] out = new double[n];
        for (int i = 0; i < n; i++) {
            double v = (first + i) * step;
            out[i] = Math.abs(v) < step * 1e-9 ? 0 : v;
        }
        return out;
    }

    /** {@code v} with as many decimals as {@code step} needs ("0.25", "10", "-3"). */
    public static String label(double v, double step) {
        int decimals = Math.max(0, (int) -Math.floor(Math.log10(step) + 1e-9));
        return String.format(Locale.ROOT, "%." + Math.min(decimals, 9) + "f", Math.abs(v) < step * 1e-6 ? 0.0 : v);
    }
}
