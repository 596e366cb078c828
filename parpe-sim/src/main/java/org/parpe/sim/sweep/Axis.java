package org.parpe.sim.sweep;

import java.util.List;
import java.util.SplittableRandom;

/**
 * One varied parameter of a sweep.
 *
 * @param name   the parameter's name
 * @param kind   how the values are chosen
 * @param lo     the smallest value
 * @param hi     the largest value
 * @param values the values of a grid, ascending for ranges, as written for lists; empty for
 *               {@link Kind#CONTINUOUS}, which only a random sweep can draw from
 */
public record Axis(String name, Kind kind, double lo, double hi, List<Double> values) {

    /** How an axis's values are chosen. */
    public enum Kind {
        /** Every integer from {@code lo} to {@code hi} ({@code N=4..12}). */
        INTEGERS,
        /** {@code K} evenly spaced values from {@code lo} to {@code hi} ({@code amp=10..40:7}). */
        EVEN,
        /** The values given ({@code phase=0.1,0.2,0.25}). */
        LIST,
        /** Any real number in {@code [lo, hi]} (random sweeps, or a parameter's own bounds). */
        CONTINUOUS
    }

    public Axis {
        values = List.copyOf(values);
    }

    /** Every integer from {@code lo} to {@code hi}. */
    public static Axis integers(String name, long lo, long hi) {
        List<Double> v = new java.util.ArrayList<>();
        for (long i = lo; i <= hi; i++) {
            v.add((double) i);
        }
        return new Axis(name, Kind.INTEGERS, lo, hi, v);
    }

    /** {@code k} evenly spaced values from {@code lo} to {@code hi} (ends included; {@code k = 1}: {@code lo}). */
    public static Axis even(String name, double lo, double hi, int k) {
        List<Double> v = new java.util.ArrayList<>();
        for (int i = 0; i < k; i++) {
            v.add(i == k - 1 && k > 1 ? hi : lo + (hi - lo) * i / Math.max(1, k - 1));
        }
        return new Axis(name, Kind.EVEN, lo, hi, v);
    }

    /** The given values. */
    public static Axis list(String name, List<Double> values) {
        double lo = values.stream().mapToDouble(Double::doubleValue).min().orElse(0);
        double hi = values.stream().mapToDouble(Double::doubleValue).max().orElse(0);
        return new Axis(name, Kind.LIST, lo, hi, values);
    }

    /** Any real number in {@code [lo, hi]}. */
    public static Axis continuous(String name, double lo, double hi) {
        return new Axis(name, Kind.CONTINUOUS, lo, hi, List.of());
    }

    /** Whether a grid can enumerate this axis (everything but {@link Kind#CONTINUOUS}). */
    public boolean enumerable() {
        return kind != Kind.CONTINUOUS;
    }

    /** One value drawn with {@code random}: uniform over the grid values, or over {@code [lo, hi]}. */
    public double draw(SplittableRandom random) {
        if (kind == Kind.CONTINUOUS) {
            return lo == hi ? lo : lo + (hi - lo) * random.nextDouble();
        }
        return values.get(random.nextInt(values.size()));
    }
}
