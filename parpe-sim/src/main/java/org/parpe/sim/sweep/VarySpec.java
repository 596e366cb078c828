package org.parpe.sim.sweep;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.parpe.core.expr.Names;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Parameter;

/**
 * Reads the text of one varied parameter, as {@code parpe sweep --vary} takes it and the IDE's
 * dialog may offer it:
 * <ul>
 * <li>{@code NAME=A..B} with integers A and B: every integer from A to B;</li>
 * <li>{@code NAME=A..B} with a fractional end: any number in [A, B] (random sweeps only);</li>
 * <li>{@code NAME=A..B:K}: K evenly spaced values from A to B;</li>
 * <li>{@code NAME=V1,V2,...}: the values given.</li>
 * </ul>
 * Every value must be one the parameter accepts (its {@code min} and {@code max}).
 */
public final class VarySpec {
    private VarySpec() {
    }

    /**
     * The axis {@code text} describes for one of {@code parameters}; a malformed text, an
     * unknown name or a value out of bounds throws with one line naming what was wrong.
     */
    public static Axis parse(String text, List<Parameter> parameters) throws SweepException {
        int eq = text.indexOf('=');
        if (eq <= 0) {
            throw new SweepException("--vary '" + text + "': expected NAME=A..B, NAME=A..B:K or NAME=V1,V2,...");
        }
        String name = text.substring(0, eq).trim();
        String body = text.substring(eq + 1).trim();
        Parameter p = find(name, parameters, text);
        String where = "--vary " + text.trim() + ": ";
        if (body.isEmpty()) {
            throw new SweepException(where + "no values after '='; expected A..B, A..B:K or V1,V2,...");
        }
        Axis axis = body.contains("..") ? range(name, body, where) : list(name, body, where);
        check(axis, p, where);
        return axis;
    }

    private static Parameter find(String name, List<Parameter> parameters, String text) throws SweepException {
        for (Parameter p : parameters) {
            if (p.name().equals(name)) {
                return p;
            }
        }
        List<String> names = parameters.stream().map(Parameter::name).toList();
        throw new SweepException("--vary " + text.trim() + ": unknown parameter '" + name + "'"
                + Names.suggest(name, names) + (names.isEmpty() ? "; the script has no <parameters>"
                : "; the script's parameters are " + String.join(", ", names)));
    }

    private static Axis range(String name, String body, String where) throws SweepException {
        int colon = body.lastIndexOf(':');
        String span = colon < 0 ? body : body.substring(0, colon);
        int dots = span.indexOf("..");
        if (dots < 0 || span.indexOf("..", dots + 2) >= 0) {
            throw new SweepException(where + "expected A..B or A..B:K, got '" + body + "'");
        }
        double a = number(span.substring(0, dots), where);
        double b = number(span.substring(dots + 2), where);
        if (a > b) {
            throw new SweepException(where + "empty range: the start " + Numbers.format(a) + " is greater than the end "
                    + Numbers.format(b));
        }
        if (colon >= 0) {
            String k = body.substring(colon + 1).trim();
            if (!k.matches("[+-]?\\d+")) {
                throw new SweepException(where + "K (the number of values) must be a whole number >= 1, got '" + k + "'");
            }
            if (new java.math.BigInteger(k).compareTo(java.math.BigInteger.valueOf(Integer.MAX_VALUE)) > 0) {
                // a whole number, only too large to count (a smaller K is weighed with the sweep's size)
                throw new SweepException(where + "K (the number of values) is " + k + ", more than the "
                        + SweepSpec.MAX_RUNS + " runs one sweep may have; use fewer values or --random COUNT");
            }
            int count = Integer.parseInt(k);
            if (count < 1) {
                throw new SweepException(where + "K (the number of values) must be >= 1, got " + count);
            }
            if (count == 1 && a != b) {
                throw new SweepException(where + "K = 1 gives a single value, but " + Numbers.format(a) + ".."
                        + Numbers.format(b) + " is a range; write " + name + "=" + Numbers.format(a) + " instead");
            }
            return Axis.even(name, a, b, count);
        }
        if (a == Math.rint(a) && b == Math.rint(b)) {
            if (b - a >= 1_000_000) {
                throw new SweepException(where + "too many integers in " + Numbers.format(a) + ".." + Numbers.format(b)
                        + " (at most 1000000); give a count with :K");
            }
            return Axis.integers(name, (long) a, (long) b);
        }
        return Axis.continuous(name, a, b);
    }

    private static Axis list(String name, String body, String where) throws SweepException {
        List<Double> values = new ArrayList<>();
        for (String part : body.split(",", -1)) {
            values.add(number(part, where));
        }
        return Axis.list(name, values);
    }

    private static double number(String text, String where) throws SweepException {
        Double v = Numbers.parsePlain(text);
        if (v == null) {
            throw new SweepException(where + "'" + text.trim() + "' is not a number");
        }
        return v;
    }

    private static void check(Axis axis, Parameter p, String where) throws SweepException {
        for (double v : new double[] {axis.lo(), axis.hi()}) {
            String problem = p.check(v);
            if (problem != null) {
                throw new SweepException(where + problem + bounds(p));
            }
        }
    }

    private static String bounds(Parameter p) {
        return String.format(Locale.ROOT, " (its bounds are %s..%s)", p.min() == null ? "-inf" : Numbers.format(p.min()),
                p.max() == null ? "+inf" : Numbers.format(p.max()));
    }
}
