package org.parpe.core.diagram;

import java.util.List;
import java.util.Set;
import org.parpe.core.expr.ExprTree;
import org.parpe.core.expr.Expression;
import org.parpe.core.expr.Node;

/**
 * Whether an expression can be evaluated before a run: it may read controls (at their declared
 * values) and the module's {@code $index}, {@code $count} and {@code $id}, but not the clock,
 * the cycle position, sensors, macros or random numbers.
 */
final class StaticValue implements ExprTree.Visitor<Boolean> {
    private static final Set<String> MODULE_VARIABLES = Set.of("index", "count", "id");
    private static final StaticValue INSTANCE = new StaticValue();

    private StaticValue() {
    }

    /** Whether {@code e} is known before a run. */
    static boolean known(Expression e) {
        return e.isConstant() || ExprTree.visit(e.root(), INSTANCE);
    }

    private boolean all(Node... nodes) {
        for (Node n : nodes) {
            if (!ExprTree.visit(n, this)) {
                return false;
            }
        }
        return true;
    }

    @Override
    public Boolean constant(double value) {
        return true;
    }

    @Override
    public Boolean variable(String name) {
        return MODULE_VARIABLES.contains(name);
    }

    @Override
    public Boolean control(int index) {
        return true;
    }

    @Override
    public Boolean macro(int index) {
        return false;
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
        return all(arg);
    }

    @Override
    public Boolean binary(String op, Node left, Node right) {
        return all(left, right);
    }

    @Override
    public Boolean logic(boolean and, Node left, Node right) {
        return all(left, right);
    }

    @Override
    public Boolean conditional(Node cond, Node then, Node otherwise) {
        return all(cond, then, otherwise);
    }

    @Override
    public Boolean function1(String name, Node arg) {
        return all(arg);
    }

    @Override
    public Boolean function2(String name, Node a, Node b) {
        return all(a, b);
    }

    @Override
    public Boolean sum(List<Node> args) {
        return all(args.toArray(new Node[0]));
    }

    @Override
    public Boolean random() {
        return false;
    }
}
