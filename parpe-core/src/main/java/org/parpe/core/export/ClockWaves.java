package org.parpe.core.export;

import java.util.Set;
import org.parpe.core.expr.ExprTree;
import org.parpe.core.expr.Expression;
import org.parpe.core.expr.Node;

/**
 * Finds expressions that are a periodic function ({@code sin cos tan mod %}) of the clock
 * ({@code $time}, {@code $btime}): on a board whose {@code double} is a 32-bit float the clock
 * loses resolution as it grows (7.8 ms steps after a day), and such a wave loses its phase with
 * it, while an automaton's {@code $phase} keeps it (docs/embedded.md). Each node answers whether
 * it depends on the clock.
 */
final class ClockWaves extends ExprTree.Question {
    private static final Set<String> PERIODIC = Set.of("sin", "cos", "tan", "mod");
    private boolean found;

    private ClockWaves() {
        super(false);
    }

    /** Whether {@code e} applies a periodic function to something that depends on the clock. */
    static boolean periodicOfClock(Expression e) {
        ClockWaves w = new ClockWaves();
        ExprTree.visit(e.root(), w);
        return w.found;
    }

    private boolean periodic(boolean clock) {
        found |= clock;
        return clock;
    }

    @Override
    public Boolean variable(String name) {
        return name.equals("time") || name.equals("btime");
    }

    @Override
    public Boolean binary(String op, Node left, Node right) {
        boolean clock = super.binary(op, left, right);
        return op.equals("%") ? periodic(clock) : clock;
    }

    @Override
    public Boolean function1(String name, Node arg) {
        boolean clock = super.function1(name, arg);
        return PERIODIC.contains(name) ? periodic(clock) : clock;
    }

    @Override
    public Boolean function2(String name, Node a, Node b) {
        boolean clock = super.function2(name, a, b);
        return PERIODIC.contains(name) ? periodic(clock) : clock;
    }
}
