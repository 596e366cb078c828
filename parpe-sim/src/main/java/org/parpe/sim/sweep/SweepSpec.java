package org.parpe.sim.sweep;

import org.parpe.sim.text.SimMsg;
import org.parpe.core.text.Message;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Parameter;

/**
 * Which runs a sweep makes: every combination of its axes' values (a grid, first axis slowest),
 * or {@code randomCount} combinations drawn from them; each combination {@code repeat} times,
 * the {@code r}-th repetition with {@code rand()} seed {@code seed + r}. A run's values depend
 * only on the specification and its index, never on the threads or the shard that computes it.
 *
 * @param axes        the varied parameters, in order
 * @param randomCount the number of random combinations, or 0 for a grid
 * @param seed        the seed of the random draws and of {@code rand()}
 * @param repeat      runs per combination, >= 1
 */
public record SweepSpec(List<Axis> axes, int randomCount, long seed, int repeat) {
    /** The most runs one sweep may have. */
    public static final int MAX_RUNS = 10_000_000;

    public SweepSpec {
        axes = List.copyOf(axes);
    }

    /** A grid over {@code axes}. */
    public static SweepSpec grid(List<Axis> axes, int repeat, long seed) {
        return new SweepSpec(axes, 0, seed, repeat);
    }

    /** {@code count} random combinations of {@code axes}. */
    public static SweepSpec random(List<Axis> axes, int count, int repeat, long seed) {
        return new SweepSpec(axes, count, seed, repeat);
    }

    /**
     * One continuous axis per parameter of {@code parameters} with a {@code min} and a
     * {@code max} (integers only when min, max and default are whole numbers), leaving out
     * {@code exclude}: the whole search space the script declares.
     */
    public static List<Axis> declaredSpace(List<Parameter> parameters, Set<String> exclude) {
        List<Axis> axes = new ArrayList<>();
        for (Parameter p : parameters) {
            if (p.min() == null || p.max() == null || exclude.contains(p.name()) || p.min().equals(p.max())) {
                continue;
            }
            axes.add(integral(p) ? Axis.integers(p.name(), p.min().longValue(), p.max().longValue())
                    : Axis.continuous(p.name(), p.min(), p.max()));
        }
        return axes;
    }

    /** Whether {@code p} looks like a count: its default and bounds are whole numbers. */
    static boolean integral(Parameter p) {
        return p.value() == Math.rint(p.value()) && p.min() != null && p.min() == Math.rint(p.min())
                && p.max() != null && p.max() == Math.rint(p.max());
    }

    /** Checks that the sweep can be made; one line per kind of problem. */
    public void check() throws SweepException {
        if (axes.isEmpty()) {
            throw new SweepException(SimMsg.NOTHING_TO_VARY);
        }
        Set<String> seen = new HashSet<>();
        for (Axis a : axes) {
            if (!seen.add(a.name())) {
                throw new SweepException(SimMsg.VARIED_TWICE, a.name());
            }
            if (randomCount == 0 && !a.enumerable()) {
                throw new SweepException(SimMsg.FRACTIONAL_ENDS, a.name(), Numbers.format(a.lo()),
                        Numbers.format(a.hi()));
            }
        }
        if (repeat < 1) {
            throw new SweepException(SimMsg.REPEAT_AT_LEAST_ONE, repeat);
        }
        if (randomCount < 0) {
            throw new SweepException(SimMsg.RANDOM_AT_LEAST_ONE, randomCount);
        }
        long runs = saturated(combinations(), repeat);
        if (runs > MAX_RUNS) {
            throw new SweepException(SimMsg.TOO_MANY_RUNS,
                    runs == Long.MAX_VALUE ? Message.of(SimMsg.MORE_THAN, "9.2e18") : runs, MAX_RUNS);
        }
    }

    /** The number of combinations (grid size, or the random count). */
    public long combinations() {
        if (randomCount > 0) {
            return randomCount;
        }
        long n = 1;
        for (Axis a : axes) {
            n = saturated(n, a.count());
        }
        return n;
    }

    /** {@code a * b}, or {@code Long.MAX_VALUE} where that overflows (both >= 0). */
    private static long saturated(long a, long b) {
        return Math.multiplyHigh(a, b) != 0 || a * b < 0 ? Long.MAX_VALUE : a * b;
    }

    /** The number of runs: combinations × repeat (after {@link #check()}). */
    public int size() {
        return (int) (combinations() * repeat);
    }

    /** Run {@code index} (0 ≤ index < {@link #size()}). */
    public Point point(int index) {
        int combination = index / repeat;
        int r = index % repeat;
        Map<String, Double> values = new LinkedHashMap<>();
        if (randomCount > 0) {
            SplittableRandom random = new SplittableRandom(mix(seed, combination));
            for (Axis a : axes) {
                values.put(a.name(), a.draw(random));
            }
        } else {
            long rest = combination;
            double[] picked = new double[axes.size()];
            for (int i = axes.size() - 1; i >= 0; i--) {
                List<Double> v = axes.get(i).values();
                picked[i] = v.get((int) (rest % v.size()));
                rest /= v.size();
            }
            for (int i = 0; i < axes.size(); i++) {
                values.put(axes.get(i).name(), picked[i]);
            }
        }
        return new Point(index, combination, r, values, seed + r);
    }

    /**
     * The runs of shard {@code k} of {@code n} (1-based) of {@code total} runs, as
     * {@code [from, to)}: consecutive blocks whose sizes differ by at most one.
     */
    public static int[] shard(int total, int k, int n) {
        if (n < 1 || k < 1 || k > n) {
            throw new IllegalArgumentException("shard " + k + "/" + n + " must have 1 <= K <= N");
        }
        return new int[] {(int) ((long) total * (k - 1) / n), (int) ((long) total * k / n)};
    }

    /** A well-mixed seed for combination {@code i} (SplitMix64's finaliser). */
    static long mix(long seed, long i) {
        long z = seed + 0x9E3779B97F4A7C15L * (i + 1);
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
