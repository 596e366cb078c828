package org.parpe.core.expr;

import java.util.List;
import java.util.Locale;
import org.parpe.core.lang.Vocabulary;

/**
 * A read-only view of a compiled expression tree for code generators (the C export): each
 * node kind is handed to a {@link Visitor} with its operands, so a generator translates the
 * very tree the interpreter evaluates instead of parsing the text again. Evaluation is not
 * affected.
 */
public final class ExprTree {
    private ExprTree() {
    }

    /** Local sensor positions that are not a fixed index: the current module and its neighbours. */
    public static final int SELF = Nodes.LocalSensor.SELF, PREV = Nodes.LocalSensor.PREV, NEXT = Nodes.LocalSensor.NEXT;

    /** Receives one node; children are passed as {@link Node}s to visit in turn. */
    public interface Visitor<R> {
        /** A number (parameters, radio words and constant sub-expressions are folded into these). */
        R constant(double value);

        /** A logical variable: {@code time btime index count id phase cycle}. */
        R variable(String name);

        /** {@code $control}, by control index. */
        R control(int index);

        /** An expression-valued macro, by macro slot. */
        R macro(int index);

        /** A global sensor reference: a flat slot {@code moduleIndex * channels + channel}. */
        R globalSensor(int slot);

        /** A local sensor reference: a group position, or {@link #SELF}, {@link #PREV}, {@link #NEXT}. */
        R localSensor(int position, int channel);

        /** Unary minus, or logical not. */
        R unary(boolean not, Node arg);

        /** One of {@code + - * / % ^ < > <= >= == !=}, evaluating the left operand first. */
        R binary(String op, Node left, Node right);

        /** {@code &&} ({@code and}) or {@code ||}, short-circuiting. */
        R logic(boolean and, Node left, Node right);

        /** {@code if(c, a, b)}, evaluating only the chosen branch. */
        R conditional(Node cond, Node then, Node otherwise);

        /** A one-argument function by its script name ({@code sin}, {@code round}, …). */
        R function1(String name, Node arg);

        /** {@code atan2 mod min max}. */
        R function2(String name, Node a, Node b);

        /** {@code sum(a, …)}, added left to right. */
        R sum(List<Node> args);

        /** {@code rand()}. */
        R random();
    }

    /**
     * A visitor whose leaves (numbers, variables, controls, macros, sensors, {@code rand()}) all
     * answer {@link #leaf()} unless a subclass says otherwise for one kind; the operators and
     * functions are the subclass's.
     */
    public abstract static class ByLeaf<R> implements Visitor<R> {
        /** What a leaf answers unless its kind's method is overridden. */
        protected abstract R leaf();

        @Override
        public R constant(double value) {
            return leaf();
        }

        @Override
        public R variable(String name) {
            return leaf();
        }

        @Override
        public R control(int index) {
            return leaf();
        }

        @Override
        public R macro(int index) {
            return leaf();
        }

        @Override
        public R globalSensor(int slot) {
            return leaf();
        }

        @Override
        public R localSensor(int position, int channel) {
            return leaf();
        }

        @Override
        public R random() {
            return leaf();
        }
    }

    /**
     * A yes/no question about a tree: each leaf answers by its kind (no, unless a subclass says
     * otherwise; a subclass always answers for variables), an operator or function by its
     * operands' answers, combined with {@code and} (stopping at the first no) or {@code or}
     * (asking every operand, so that a subclass sees the whole tree).
     */
    public abstract static class Question extends ByLeaf<Boolean> {
        private final boolean and;

        /** A question whose operators answer yes when all operands do ({@code and}) or when any does. */
        protected Question(boolean and) {
            this.and = and;
        }

        /** The operands' answers, combined. */
        protected final boolean operands(Node... nodes) {
            boolean any = false;
            for (Node n : nodes) {
                boolean yes = visit(n, this);
                if (and && !yes) {
                    return false;
                }
                any |= yes;
            }
            return and || any;
        }

        @Override
        protected Boolean leaf() {
            return false;
        }

        @Override
        public abstract Boolean variable(String name);

        @Override
        public Boolean unary(boolean not, Node arg) {
            return operands(arg);
        }

        @Override
        public Boolean binary(String op, Node left, Node right) {
            return operands(left, right);
        }

        @Override
        public Boolean logic(boolean and, Node left, Node right) {
            return operands(left, right);
        }

        @Override
        public Boolean conditional(Node cond, Node then, Node otherwise) {
            return operands(cond, then, otherwise);
        }

        @Override
        public Boolean function1(String name, Node arg) {
            return operands(arg);
        }

        @Override
        public Boolean function2(String name, Node a, Node b) {
            return operands(a, b);
        }

        @Override
        public Boolean sum(List<Node> args) {
            return operands(args.toArray(new Node[0]));
        }
    }

    /** Hands {@code n} to the matching method of {@code v}. */
    public static <R> R visit(Node n, Visitor<R> v) {
        if (n instanceof Nodes.Const c) {
            return v.constant(c.value);
        } else if (n instanceof Nodes.Var x) {
            return v.variable(Vocabulary.LOGICAL_VARIABLES.get(x.which));
        } else if (n instanceof Nodes.ControlRef c) {
            return v.control(c.index);
        } else if (n instanceof Nodes.MacroRef m) {
            return v.macro(m.index);
        } else if (n instanceof Nodes.GlobalSensor g) {
            return v.globalSensor(g.slot);
        } else if (n instanceof Nodes.LocalSensor l) {
            return v.localSensor(l.position, l.channel);
        } else if (n instanceof Nodes.Unary u) {
            return v.unary(u.not, u.arg);
        } else if (n instanceof Nodes.Binary b) {
            return v.binary(Nodes.Binary.SYMBOLS[b.op], b.left, b.right);
        } else if (n instanceof Nodes.And l) {
            return v.logic(!(l instanceof Nodes.Or), l.left, l.right);
        } else if (n instanceof Nodes.If f) {
            return v.conditional(f.cond, f.then, f.otherwise);
        } else if (n instanceof Nodes.Func1 f) {
            return v.function1(f.f.name().toLowerCase(Locale.ROOT), f.arg);
        } else if (n instanceof Nodes.Func2 f) {
            return v.function2(f.f.name().toLowerCase(Locale.ROOT), f.a, f.b);
        } else if (n instanceof Nodes.Sum s) {
            return v.sum(List.of(s.args));
        } else if (n instanceof Nodes.Rand) {
            return v.random();
        }
        throw new IllegalArgumentException("unknown expression node " + n.getClass().getName());
    }
}
