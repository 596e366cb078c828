package org.parpe.core.diagram;

import java.util.Set;
import org.parpe.core.expr.ExprTree;
import org.parpe.core.expr.Expression;

/**
 * Whether an expression can be evaluated before a run: it may read controls (at their declared
 * values) and the module's {@code $index}, {@code $count} and {@code $id}, but not the clock,
 * the cycle position, sensors, macros or random numbers.
 */
final class StaticValue extends ExprTree.Question {
    private static final Set<String> MODULE_VARIABLES = Set.of("index", "count", "id");
    private static final StaticValue INSTANCE = new StaticValue();

    private StaticValue() {
        super(true);
    }

    /** Whether {@code e} is known before a run. */
    static boolean known(Expression e) {
        return e.isConstant() || ExprTree.visit(e.root(), INSTANCE);
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
}
