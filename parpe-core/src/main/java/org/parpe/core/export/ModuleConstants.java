package org.parpe.core.export;

import java.util.Set;
import org.parpe.core.expr.ExprTree;
import org.parpe.core.expr.Node;

/**
 * Finds the sub-expressions of a state's angle that are worth keeping per module (issue 36 item
 * 3): built from numbers and {@code $index $count $id} only, so the same for a module at every
 * tick (an instance's group does not change while it runs), and costly (a function, a division,
 * a power or a remainder). The exported program computes such a value at a module's first tick,
 * with the same operations as before, and reads it afterwards ({@code PARSL_KEEP}); the trace
 * does not change. {@code 2*cos(pi*$index/$count)} is one; {@code $index/$count} inside
 * {@code sin(2*pi*($phase + $index/$count))} another.
 */
final class ModuleConstants {
    private static final Set<String> MODULE = Set.of("index", "count", "id");

    private ModuleConstants() {
    }

    /** Whether the value of {@code n} is worth keeping per module. */
    static boolean worthKeeping(Node n) {
        return ExprTree.visit(n, new Invariant()) && ExprTree.visit(n, new UsesModule())
                && ExprTree.visit(n, new Costly());
    }

    /** Every leaf a number or a module's own variable. */
    private static final class Invariant extends ExprTree.Question {
        Invariant() {
            super(true);
        }

        @Override
        public Boolean constant(double value) {
            return true;
        }

        @Override
        public Boolean variable(String name) {
            return MODULE.contains(name);
        }
    }

    /** Some leaf a module's own variable (a tree of numbers only is folded by the loader). */
    private static final class UsesModule extends ExprTree.Question {
        UsesModule() {
            super(false);
        }

        @Override
        public Boolean variable(String name) {
            return MODULE.contains(name);
        }
    }

    /** Some node a function, a division, a power or a remainder: dearer than reading a kept value. */
    private static final class Costly extends ExprTree.Question {
        Costly() {
            super(false);
        }

        @Override
        public Boolean variable(String name) {
            return false;
        }

        @Override
        public Boolean binary(String op, Node left, Node right) {
            return super.binary(op, left, right) || "/%^".contains(op);
        }

        @Override
        public Boolean function1(String name, Node arg) {
            return true;
        }

        @Override
        public Boolean function2(String name, Node a, Node b) {
            return true;
        }
    }
}
