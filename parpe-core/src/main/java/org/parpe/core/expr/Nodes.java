package org.parpe.core.expr;

import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;


/**
 * The node kinds of compiled expressions. Every operator and function checks that its result
 * is finite, so that {@code 1/0}, {@code log(0)} or {@code sqrt(-1)} stop the run where they
 * happen (PARSL.md §8) even when a later comparison would hide them.
 */
final class Nodes {
    private Nodes() {
    }

    static double finite(double v, Msg what) {
        if (Double.isFinite(v)) {
            return v;
        }
        throw new EvalException(Msg.NOT_FINITE, Message.of(what));
    }

    /** A number. */
    static final class Const extends Node {
        final double value;

        Const(double value) {
            this.value = value;
        }

        @Override
        public double eval(EvalContext c) {
            return value;
        }
    }

    /** A logical variable or other context field: one subclass per variable ({@link #of}), so no switch per evaluation. */
    abstract static class Var extends Node {
        static final int TIME = 0, BTIME = 1, INDEX = 2, COUNT = 3, ID = 4, PHASE = 5, CYCLE = 6;
        final int which;

        Var(int which) {
            this.which = which;
        }

        /** The node reading variable {@code which}. */
        static Var of(int which) {
            return Arith.variable(which);
        }
    }

    /** {@code $control}. */
    static final class ControlRef extends Node {
        final int index;

        ControlRef(int index) {
            this.index = index;
        }

        @Override
        public double eval(EvalContext c) {
            return c.controls[index];
        }
    }

    /** An expression-valued macro. */
    static final class MacroRef extends Node {
        final int index;

        MacroRef(int index) {
            this.index = index;
        }

        @Override
        public double eval(EvalContext c) {
            return c.macros[index];
        }
    }

    /** {@code $<id>_<sensor>[_<arg>]}: a fixed sensor-table slot. */
    static final class GlobalSensor extends Node {
        final int slot;

        GlobalSensor(int slot) {
            this.slot = slot;
        }

        @Override
        public double eval(EvalContext c) {
            return c.sensors.getSlot(slot);
        }
    }

    /** {@code $_n_…}, {@code $_self_…}, {@code $_prev_…}, {@code $_next_…}. */
    static final class LocalSensor extends Node {
        static final int SELF = -1, PREV = -2, NEXT = -3;
        final int position;
        final int channel;

        LocalSensor(int position, int channel) {
            this.position = position;
            this.channel = channel;
        }

        @Override
        public double eval(EvalContext c) {
            int n = c.group.length;
            int p;
            if (position == SELF) {
                p = c.index;
            } else if (position == PREV) {
                p = (c.index - 1 + n) % n;
            } else if (position == NEXT) {
                p = (c.index + 1) % n;
            } else {
                p = position;
            }
            return c.sensors.getSlot(c.group[p] * org.parpe.core.sensor.Channel.count() + channel);
        }
    }

    /** Unary minus and logical not. */
    static final class Unary extends Node {
        final boolean not;
        final Node arg;

        Unary(boolean not, Node arg) {
            this.not = not;
            this.arg = arg;
        }

        @Override
        public double eval(EvalContext c) {
            double v = arg.eval(c);
            return not ? (v == 0 ? 1 : 0) : -v;
        }
    }

    /** Binary arithmetic and comparison operators. */
    static class Binary extends Node {
        static final int ADD = 0, SUB = 1, MUL = 2, DIV = 3, MOD = 4, POW = 5,
                LT = 6, GT = 7, LE = 8, GE = 9, EQ = 10, NE = 11;
        static final String[] SYMBOLS = {"+", "-", "*", "/", "%", "^", "<", ">", "<=", ">=", "==", "!="};
        final int op;
        final Node left;
        final Node right;

        Binary(int op, Node left, Node right) {
            this.op = op;
            this.left = left;
            this.right = right;
        }

        /**
         * The node for {@code left op right}: with a constant side, one that does not evaluate
         * the constant per call (half the calls of {@code 2*pi*$phase}); the same arithmetic.
         */
        static Binary of(int op, Node left, Node right) {
            Binary special = Arith.binary(op, left, right);
            if (special != null) {
                return special;
            }
            if (left instanceof Const && !(right instanceof Const)) {
                return new ConstLeft(op, left, right);
            }
            if (right instanceof Const && !(left instanceof Const)) {
                return new ConstRight(op, left, right);
            }
            return new Binary(op, left, right);
        }

        @Override
        public double eval(EvalContext c) {
            double a = left.eval(c);
            return apply(op, a, right.eval(c));
        }

        static double apply(int op, double a, double b) {
            switch (op) {
                case ADD: return add(a, b);
                case SUB: return sub(a, b);
                case MUL: return mul(a, b);
                case DIV: return div(a, b);
                case MOD:
                    if (b == 0) {
                        throw new EvalException(Msg.REMAINDER_BY_ZERO);
                    }
                    return a % b;
                case POW:
                    double pw = Math.pow(a, b);
                    if (!Double.isFinite(pw)) {
                        throw new EvalException(Msg.NOT_FINITE,
                                org.parpe.core.lang.Numbers.brief(a) + "^" + org.parpe.core.lang.Numbers.brief(b));
                    }
                    return pw;
                case LT: return a < b ? 1 : 0;
                case GT: return a > b ? 1 : 0;
                case LE: return a <= b ? 1 : 0;
                case GE: return a >= b ? 1 : 0;
                case EQ: return a == b ? 1 : 0;
                default: return a != b ? 1 : 0;
            }
        }

        static double add(double a, double b) {
            return finite(a + b, Msg.A_SUM);
        }

        static double sub(double a, double b) {
            return finite(a - b, Msg.A_DIFFERENCE);
        }

        static double mul(double a, double b) {
            return finite(a * b, Msg.A_PRODUCT);
        }

        static double div(double a, double b) {
            if (b == 0) {
                throw new EvalException(Msg.DIVISION_BY_ZERO);
            }
            return finite(a / b, Msg.A_QUOTIENT);
        }
    }

    /** A {@link Binary} whose left side is a constant. */
    static final class ConstLeft extends Binary {
        private final double k;

        ConstLeft(int op, Node left, Node right) {
            super(op, left, right);
            this.k = ((Const) left).value;
        }

        @Override
        public double eval(EvalContext c) {
            return apply(op, k, right.eval(c));
        }
    }

    /** A {@link Binary} whose right side is a constant. */
    static final class ConstRight extends Binary {
        private final double k;

        ConstRight(int op, Node left, Node right) {
            super(op, left, right);
            this.k = ((Const) right).value;
        }

        @Override
        public double eval(EvalContext c) {
            return apply(op, left.eval(c), k);
        }
    }

    /**
     * {@code &&}, short-circuiting: 1 when both sides are non-zero, the right side evaluated only
     * when the left is non-zero. {@link Or} shares its two sides; neither tests per call which
     * operator it is.
     */
    static class And extends Node {
        final Node left;
        final Node right;

        And(Node left, Node right) {
            this.left = left;
            this.right = right;
        }

        @Override
        public double eval(EvalContext c) {
            return left.eval(c) != 0 && right.eval(c) != 0 ? 1 : 0;
        }
    }

    /** {@code ||}, short-circuiting: 1 when either side is non-zero, the right side evaluated only when the left is zero. */
    static final class Or extends And {
        Or(Node left, Node right) {
            super(left, right);
        }

        @Override
        public double eval(EvalContext c) {
            return left.eval(c) != 0 || right.eval(c) != 0 ? 1 : 0;
        }
    }

    /** {@code if(c, a, b)}, evaluating only the chosen branch. */
    static final class If extends Node {
        final Node cond;
        final Node then;
        final Node otherwise;

        If(Node cond, Node then, Node otherwise) {
            this.cond = cond;
            this.then = then;
            this.otherwise = otherwise;
        }

        @Override
        public double eval(EvalContext c) {
            return cond.eval(c) != 0 ? then.eval(c) : otherwise.eval(c);
        }
    }

    /** One-argument functions ({@link #of} gives a specialised node for the commonest). */
    static class Func1 extends Node {
        final Functions.F1 f;
        final Node arg;

        Func1(Functions.F1 f, Node arg) {
            this.f = f;
            this.arg = arg;
        }

        /** The node for {@code f(arg)}. */
        static Func1 of(Functions.F1 f, Node arg) {
            Func1 special = Arith.function(f, arg);
            return special != null ? special : new Func1(f, arg);
        }

        @Override
        public double eval(EvalContext c) {
            double x = arg.eval(c);
            return checked(f.apply(x), x);
        }

        /** {@code v}, the value of the function at {@code x}, unless it is not finite. */
        final double checked(double v, double x) {
            if (Double.isFinite(v)) {
                return v;
            }
            throw new EvalException(Msg.FUNCTION_NOT_FINITE, f.label(), org.parpe.core.lang.Numbers.brief(x));
        }
    }

    /** Two-argument functions. */
    static final class Func2 extends Node {
        final Functions.F2 f;
        final Node a;
        final Node b;

        Func2(Functions.F2 f, Node a, Node b) {
            this.f = f;
            this.a = a;
            this.b = b;
        }

        @Override
        public double eval(EvalContext c) {
            return f.apply(a.eval(c), b.eval(c));
        }
    }

    /** {@code sum(a, …)}. */
    static final class Sum extends Node {
        final Node[] args;

        Sum(Node[] args) {
            this.args = args;
        }

        @Override
        public double eval(EvalContext c) {
            double s = 0;
            for (Node n : args) {
                s += n.eval(c);
            }
            return finite(s, Msg.SUM_CALL);
        }
    }

    /** {@code rand()}: uniform in [0, 1) from the run's seeded generator. */
    static final class Rand extends Node {
        @Override
        public double eval(EvalContext c) {
            return c.random.nextDouble();
        }
    }

    static int slot(int moduleIndex, int channel) {
        return moduleIndex * org.parpe.core.sensor.Channel.count() + channel;
    }

}
