package org.parpe.core.expr;

import static org.parpe.core.expr.Nodes.Binary.ADD;
import static org.parpe.core.expr.Nodes.Binary.DIV;
import static org.parpe.core.expr.Nodes.Binary.MUL;
import static org.parpe.core.expr.Nodes.Binary.SUB;

/**
 * Specialised nodes for what angle expressions are mostly made of: the four arithmetic
 * operators (with a constant side or without), the logical variables, {@code sin} and
 * {@code cos}. A tree of these evaluates without a switch per node and with call sites that see
 * few node classes, so the JIT can inline them (the scheduler evaluates one expression per
 * module per tick: issue 36's 30 M module-updates/s). Each is a subclass of the general node
 * ({@link Nodes.Binary}, {@link Nodes.Var}, {@link Nodes.Func1}) with the same fields, so
 * {@link ExprTree}, folding and the C export see the general kind; each computes with the
 * general node's arithmetic and checks ({@link Nodes.Binary#add} …), so values and error
 * messages are the same bit for bit. Addition and multiplication commute exactly in IEEE 754,
 * so one class serves a constant on either side.
 */
final class Arith {
    private Arith() {
    }

    /** The specialised node for {@code left op right}, or null when the general one serves. */
    static Nodes.Binary binary(int op, Node left, Node right) {
        boolean kl = left instanceof Nodes.Const;
        boolean kr = right instanceof Nodes.Const;
        if (kl && kr) {
            return null; // folded at load, or kept to fail at run time
        }
        switch (op) {
            case ADD: return kl || kr ? new AddK(left, right) : new Add(left, right);
            case SUB: return kl ? new KSub(left, right) : kr ? new SubK(left, right) : new Sub(left, right);
            case MUL: return kl || kr ? new MulK(left, right) : new Mul(left, right);
            case DIV: return kl ? new KDiv(left, right) : kr ? new DivK(left, right) : new Div(left, right);
            default: return null;
        }
    }

    /** The node reading logical variable {@code which} ({@link Nodes.Var#TIME} …). */
    static Nodes.Var variable(int which) {
        switch (which) {
            case Nodes.Var.TIME: return new Time();
            case Nodes.Var.BTIME: return new BTime();
            case Nodes.Var.INDEX: return new Index();
            case Nodes.Var.COUNT: return new Count();
            case Nodes.Var.ID: return new Id();
            case Nodes.Var.PHASE: return new Phase();
            default: return new Cycle();
        }
    }

    /** The specialised node for {@code f(arg)}, or null when the general one serves. */
    static Nodes.Func1 function(Functions.F1 f, Node arg) {
        switch (f) {
            case SIN: return new Sin(arg);
            case COS: return new Cos(arg);
            default: return null;
        }
    }

    private static double constant(Node n) {
        return ((Nodes.Const) n).value;
    }

    /** {@code a + b}. */
    static final class Add extends Nodes.Binary {
        Add(Node left, Node right) {
            super(ADD, left, right);
        }

        @Override
        public double eval(EvalContext c) {
            double a = left.eval(c);
            return add(a, right.eval(c));
        }
    }

    /** {@code a + k} or {@code k + a}. */
    static final class AddK extends Nodes.Binary {
        private final double k;
        private final Node x;

        AddK(Node left, Node right) {
            super(ADD, left, right);
            boolean kl = left instanceof Nodes.Const;
            this.k = constant(kl ? left : right);
            this.x = kl ? right : left;
        }

        @Override
        public double eval(EvalContext c) {
            return add(x.eval(c), k);
        }
    }

    /** {@code a - b}. */
    static final class Sub extends Nodes.Binary {
        Sub(Node left, Node right) {
            super(SUB, left, right);
        }

        @Override
        public double eval(EvalContext c) {
            double a = left.eval(c);
            return sub(a, right.eval(c));
        }
    }

    /** {@code a - k}. */
    static final class SubK extends Nodes.Binary {
        private final double k;

        SubK(Node left, Node right) {
            super(SUB, left, right);
            this.k = constant(right);
        }

        @Override
        public double eval(EvalContext c) {
            return sub(left.eval(c), k);
        }
    }

    /** {@code k - a}. */
    static final class KSub extends Nodes.Binary {
        private final double k;

        KSub(Node left, Node right) {
            super(SUB, left, right);
            this.k = constant(left);
        }

        @Override
        public double eval(EvalContext c) {
            return sub(k, right.eval(c));
        }
    }

    /** {@code a * b}. */
    static final class Mul extends Nodes.Binary {
        Mul(Node left, Node right) {
            super(MUL, left, right);
        }

        @Override
        public double eval(EvalContext c) {
            double a = left.eval(c);
            return mul(a, right.eval(c));
        }
    }

    /** {@code a * k} or {@code k * a}. */
    static final class MulK extends Nodes.Binary {
        private final double k;
        private final Node x;

        MulK(Node left, Node right) {
            super(MUL, left, right);
            boolean kl = left instanceof Nodes.Const;
            this.k = constant(kl ? left : right);
            this.x = kl ? right : left;
        }

        @Override
        public double eval(EvalContext c) {
            return mul(x.eval(c), k);
        }
    }

    /** {@code a / b}. */
    static final class Div extends Nodes.Binary {
        Div(Node left, Node right) {
            super(DIV, left, right);
        }

        @Override
        public double eval(EvalContext c) {
            double a = left.eval(c);
            return div(a, right.eval(c));
        }
    }

    /** {@code a / k}. */
    static final class DivK extends Nodes.Binary {
        private final double k;

        DivK(Node left, Node right) {
            super(DIV, left, right);
            this.k = constant(right);
        }

        @Override
        public double eval(EvalContext c) {
            return div(left.eval(c), k);
        }
    }

    /** {@code k / a}. */
    static final class KDiv extends Nodes.Binary {
        private final double k;

        KDiv(Node left, Node right) {
            super(DIV, left, right);
            this.k = constant(left);
        }

        @Override
        public double eval(EvalContext c) {
            return div(k, right.eval(c));
        }
    }

    /** {@code sin(a)}. */
    static final class Sin extends Nodes.Func1 {
        Sin(Node arg) {
            super(Functions.F1.SIN, arg);
        }

        @Override
        public double eval(EvalContext c) {
            double x = arg.eval(c);
            return checked(Math.sin(x), x);
        }
    }

    /** {@code cos(a)}. */
    static final class Cos extends Nodes.Func1 {
        Cos(Node arg) {
            super(Functions.F1.COS, arg);
        }

        @Override
        public double eval(EvalContext c) {
            double x = arg.eval(c);
            return checked(Math.cos(x), x);
        }
    }

    /** {@code $time}. */
    static final class Time extends Nodes.Var {
        Time() {
            super(TIME);
        }

        @Override
        public double eval(EvalContext c) {
            return c.time;
        }
    }

    /** {@code $btime}. */
    static final class BTime extends Nodes.Var {
        BTime() {
            super(BTIME);
        }

        @Override
        public double eval(EvalContext c) {
            return c.btime;
        }
    }

    /** {@code $index}. */
    static final class Index extends Nodes.Var {
        Index() {
            super(INDEX);
        }

        @Override
        public double eval(EvalContext c) {
            return c.index;
        }
    }

    /** {@code $count}. */
    static final class Count extends Nodes.Var {
        Count() {
            super(COUNT);
        }

        @Override
        public double eval(EvalContext c) {
            return c.count;
        }
    }

    /** {@code $id}. */
    static final class Id extends Nodes.Var {
        Id() {
            super(ID);
        }

        @Override
        public double eval(EvalContext c) {
            return c.id;
        }
    }

    /** {@code $phase}. */
    static final class Phase extends Nodes.Var {
        Phase() {
            super(PHASE);
        }

        @Override
        public double eval(EvalContext c) {
            return c.phase;
        }
    }

    /** {@code $cycle}. */
    static final class Cycle extends Nodes.Var {
        Cycle() {
            super(CYCLE);
        }

        @Override
        public double eval(EvalContext c) {
            return c.cycle;
        }
    }
}
