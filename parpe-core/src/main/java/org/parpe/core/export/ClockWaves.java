package org.parpe.core.export;

import java.util.List;
import java.util.Set;
import org.parpe.core.expr.ExprTree;
import org.parpe.core.expr.Expression;
import org.parpe.core.expr.Node;

/**
 * Finds expressions that are a periodic function ({@code sin cos tan mod %}) of the clock
 * ({@code $time}, {@code $btime}): on a board whose {@code double} is a 32-bit float the clock
 * loses resolution as it grows (7.8 ms steps after a day), and such a wave loses its phase with
 * it, while an automaton's {@code $phase} stays exact (docs/embedded.md).
 */
final class ClockWaves implements ExprTree.Visitor<Boolean> {
    private static final Set<String> PERIODIC = Set.of("sin", "cos", "tan", "mod");
    private boolean found;

    private ClockWaves() {
    }

    /** Whether {@code e} applies a periodic function to something that depends on the clock. */
    static boolean periodicOfClock(Expression e) {
        ClockWaves w = new ClockWaves();
        ExprTree.visit(e.root(), w);
        return w.found;
    }

    /** Visits every node (no short cut, so that a wave anywhere in the tree is found); whether one depends on the clock. */
    private boolean any(Node... nodes) {
        boolean clock = false;
        for (Node n : nodes) {
            clock |= ExprTree.visit(n, this);
        }
        return clock;
    }

    private boolean periodic(boolean clock) {
        found |= clock;
        return clock;
    }

    @Override
    public Boolean constant(double value) {
        return false;
    }

    @Override
    public Boolean variable(String name) {
        return name.equals("time") || name.equals("btime");
    }

    @Override
    public Boolean control(int index) {
        return false;
    }

    @Override
    public Boolean macro(int index) {
        return false; // a macro's own expression is checked where it is written
    }

    @Override
    public Boolean globalSensor(int slot) {
        return false;
    }

    @Override
    public Boolean localSensor(int position, int channel) {
        return false;
    }

    @Override
    public Boolean unary(boolean not, Node arg) {
        return any(arg);
    }

    @Override
    public Boolean binary(String op, Node left, Node right) {
        boolean clock = any(left, right);
        return op.equals("%") ? periodic(clock) : clock;
    }

    @Override
    public Boolean logic(boolean and, Node left, Node right) {
        return any(left, right);
    }

    @Override
    public Boolean conditional(Node cond, Node then, Node otherwise) {
        return any(cond, then, otherwise);
    }

    @Override
    public Boolean function1(String name, Node arg) {
        boolean clock = any(arg);
        return PERIODIC.contains(name) ? periodic(clock) : clock;
    }

    @Override
    public Boolean function2(String name, Node a, Node b) {
        boolean clock = any(a, b);
        return PERIODIC.contains(name) ? periodic(clock) : clock;
    }

    @Override
    public Boolean sum(List<Node> args) {
        return any(args.toArray(Node[]::new));
    }

    @Override
    public Boolean random() {
        return false;
    }
}
