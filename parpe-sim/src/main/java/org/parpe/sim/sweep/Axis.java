package org.parpe.sim.sweep;

import java.util.List;
import java.util.SplittableRandom;
import org.parpe.core.lang.Numbers;
import org.parpe.sim.text.SimMsg;

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
        values = values instanceof Computed ? values : List.copyOf(values);
    }

    /** Every integer from {@code lo} to {@code hi} (computed when asked: a range may hold 10^12 of them). */
    public static Axis integers(String name, long lo, long hi) {
        long count = hi - lo + 1;
        return new Axis(name, Kind.INTEGERS, lo, hi, new Computed(count, i -> (double) (lo + i)));
    }

    /** {@code k} evenly spaced values from {@code lo} to {@code hi} (ends included; {@code k = 1}: {@code lo}). */
    public static Axis even(String name, double lo, double hi, int k) {
        return new Axis(name, Kind.EVEN, lo, hi,
                new Computed(k, i -> i == k - 1 && k > 1 ? hi : lo + (hi - lo) * i / Math.max(1, k - 1)));
    }

    /** How many values a grid has on this axis (0 for {@link Kind#CONTINUOUS}); may exceed {@code values().size()}. */
    public long count() {
        return values instanceof Computed c ? c.count : values.size();
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

    /**
     * What to say of a best {@code value} at one end of this axis ("at its upper bound 70: widen
     * the range"), where the best may lie beyond it; empty inside the range, and for an axis of
     * one value.
     */
    public String atBound(double value) {
        if (lo == hi) {
            return "";
        }
        SimMsg end = value == hi ? SimMsg.AT_UPPER_BOUND : value == lo ? SimMsg.AT_LOWER_BOUND : null;
        return end == null ? "" : end.text(Numbers.format(value));
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
        long n = count();
        return n <= Integer.MAX_VALUE ? values.get(random.nextInt((int) n)) : lo + random.nextLong(n);
    }

    /**
     * The values of a range, computed from their index instead of stored, so that a sweep too
     * big to run is refused by its count instead of filling the memory first. Lists longer
     * than {@code Integer.MAX_VALUE} report that size; {@link #count()} is exact.
     */
    private static final class Computed extends java.util.AbstractList<Double> implements java.util.RandomAccess {
        private final long count;
        private final java.util.function.LongToDoubleFunction value;

        Computed(long count, java.util.function.LongToDoubleFunction value) {
            this.count = count;
            this.value = value;
        }

        @Override
        public Double get(int index) {
            if (index < 0 || index >= size()) {
                throw new IndexOutOfBoundsException(index);
            }
            return value.applyAsDouble(index);
        }

        @Override
        public int size() {
            return (int) Math.min(count, Integer.MAX_VALUE);
        }

        @Override
        public String toString() {
            return count <= 20 ? super.toString() : "[" + get(0) + ", ..., " + value.applyAsDouble(count - 1) + "] ("
                    + count + " values)";
        }
    }
}
