package org.parpe.sim.sweep;

import org.parpe.sim.text.SimMsg;
import org.parpe.core.text.Message;
import java.util.ArrayList;
import java.util.List;
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
            throw new SweepException(SimMsg.VARY_SYNTAX, text);
        }
        String name = text.substring(0, eq).trim();
        String body = text.substring(eq + 1).trim();
        Parameter p = find(name, parameters, text);
        String where = text.trim();
        if (body.isEmpty()) {
            throw at(where, SimMsg.NO_VALUES);
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
        throw at(text.trim(), SimMsg.UNKNOWN_PARAMETER, name, Names.suggest(name, names), names.isEmpty()
                ? Message.of(SimMsg.NO_PARAMETERS) : Message.of(SimMsg.PARAMETERS_ARE, String.join(", ", names)));
    }

    private static Axis range(String name, String body, String where) throws SweepException {
        int colon = body.lastIndexOf(':');
        String span = colon < 0 ? body : body.substring(0, colon);
        int dots = span.indexOf("..");
        if (dots < 0 || span.indexOf("..", dots + 2) >= 0) {
            throw at(where, SimMsg.RANGE_SYNTAX, body);
        }
        double a = number(span.substring(0, dots), where);
        double b = number(span.substring(dots + 2), where);
        if (a > b) {
            throw at(where, SimMsg.EMPTY_RANGE, Numbers.format(a), Numbers.format(b));
        }
        if (colon >= 0) {
            String k = body.substring(colon + 1).trim();
            if (!k.matches("[+-]?\\d+")) {
                throw at(where, SimMsg.K_NOT_WHOLE, k);
            }
            if (new java.math.BigInteger(k).compareTo(java.math.BigInteger.valueOf(Integer.MAX_VALUE)) > 0) {
                // a whole number, only too large to count (a smaller K is weighed with the sweep's size)
                throw at(where, SimMsg.K_TOO_LARGE, k, SweepSpec.MAX_RUNS);
            }
            int count = Integer.parseInt(k);
            if (count < 1) {
                throw at(where, SimMsg.K_BELOW_ONE, count);
            }
            if (count == 1 && a != b) {
                throw at(where, SimMsg.K_ONE_RANGE, Numbers.format(a), Numbers.format(b), name);
            }
            return Axis.even(name, a, b, count);
        }
        if (a == Math.rint(a) && b == Math.rint(b)) {
            if (b - a >= 1_000_000) {
                throw at(where, SimMsg.TOO_MANY_INTEGERS, Numbers.format(a), Numbers.format(b));
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
            throw at(where, SimMsg.NOT_A_NUMBER, text.trim());
        }
        return v;
    }

    private static void check(Axis axis, Parameter p, String where) throws SweepException {
        for (double v : new double[] {axis.lo(), axis.hi()}) {
            Message problem = p.problem(v);
            if (problem != null) {
                throw at(where, SimMsg.WITH_BOUNDS, problem, p.min() == null ? "-inf" : Numbers.format(p.min()),
                        p.max() == null ? "+inf" : Numbers.format(p.max()));
            }
        }
    }

    /** The problem {@code key} with {@code args} of the specification {@code --vary WHERE}. */
    private static SweepException at(String where, SimMsg key, Object... args) {
        return new SweepException(SimMsg.VARY_WHERE, where, Message.of(key, args));
    }
}
