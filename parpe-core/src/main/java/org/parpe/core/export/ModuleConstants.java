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
    /** The variables a tick does not change while it runs through the modules. */
    private static final Set<String> PER_TICK = Set.of("time", "btime", "cycle");

    private ModuleConstants() {
    }

    /** Whether the value of {@code n} is worth keeping per module. */
    static boolean worthKeeping(Node n) {
        return ExprTree.visit(n, new Leaves(MODULE, false)) && ExprTree.visit(n, new UsesModule())
                && ExprTree.visit(n, new Costly());
    }

    /**
     * Whether the value of {@code n} is the same for every module of an instance in a tick, or for
     * every one with the same {@code $cycle}, and worth computing once (issue 36 item 3): built
     * from numbers, controls, macros, global sensors, {@code $time}, {@code $btime} and {@code
     * $cycle} only (a tick changes none of them while it runs through the modules), with one of
     * them, and costly. The unchecked form of the common case computes it for the first module
     * and reuses it ({@code parsl_memo}).
     */
    static boolean worthSharing(Node n) {
        return ExprTree.visit(n, new Leaves(PER_TICK, true)) && ExprTree.visit(n, new Costly())
                && !ExprTree.visit(n, new Leaves(Set.of(), false));
    }

    /** Whether {@code n} reads {@code $cycle}. */
    static boolean readsCycle(Node n) {
        return ExprTree.visit(n, new ExprTree.Question(false) {
            @Override
            public Boolean variable(String name) {
                return name.equals("cycle");
            }
        });
    }

    /**
     * Every leaf a number, one of {@code variables}, or (with {@code inputs}) a control, a macro or
     * a global sensor: with no variables, a tree of numbers; with a module's own, the same for the
     * module at every tick; with the tick's, the same for all modules in a tick.
     */
    private static final class Leaves extends ExprTree.Question {
        private final Set<String> variables;
        private final boolean inputs;

        Leaves(Set<String> variables, boolean inputs) {
            super(true);
            this.variables = variables;
            this.inputs = inputs;
        }

        @Override
        public Boolean constant(double value) {
            return true;
        }

        @Override
        public Boolean control(int index) {
            return inputs;
        }

        @Override
        public Boolean macro(int index) {
            return inputs;
        }

        @Override
        public Boolean globalSensor(int slot) {
            return inputs;
        }

        @Override
        public Boolean variable(String name) {
            return variables.contains(name);
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
