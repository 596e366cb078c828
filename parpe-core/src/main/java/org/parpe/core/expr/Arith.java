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
 * so one class serves a constant on either side. Each row of the tables below is its own
 * (anonymous) class for that reason: the rows differ only in what {@code eval} computes.
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
        if (!kl && !kr) {
            return variables(op, left, right);
        }
        double k = ((Nodes.Const) (kl ? left : right)).value;
        Node x = kl ? right : left;
        switch (op) {
            case ADD: return new Nodes.Binary(op, left, right) {
                @Override public double eval(EvalContext c) { return add(x.eval(c), k); } };
            case MUL: return new Nodes.Binary(op, left, right) {
                @Override public double eval(EvalContext c) { return mul(x.eval(c), k); } };
            case SUB: return kl ? new Nodes.Binary(op, left, right) {
                @Override public double eval(EvalContext c) { return sub(k, x.eval(c)); } }
                : new Nodes.Binary(op, left, right) {
                @Override public double eval(EvalContext c) { return sub(x.eval(c), k); } };
            case DIV: return kl ? new Nodes.Binary(op, left, right) {
                @Override public double eval(EvalContext c) { return div(k, x.eval(c)); } }
                : new Nodes.Binary(op, left, right) {
                @Override public double eval(EvalContext c) { return div(x.eval(c), k); } };
            default: return null;
        }
    }

    /** {@code left op right}, neither side a constant (the left operand evaluated first). */
    private static Nodes.Binary variables(int op, Node left, Node right) {
        switch (op) {
            case ADD: return new Nodes.Binary(op, left, right) {
                @Override public double eval(EvalContext c) { return add(left.eval(c), right.eval(c)); } };
            case SUB: return new Nodes.Binary(op, left, right) {
                @Override public double eval(EvalContext c) { return sub(left.eval(c), right.eval(c)); } };
            case MUL: return new Nodes.Binary(op, left, right) {
                @Override public double eval(EvalContext c) { return mul(left.eval(c), right.eval(c)); } };
            case DIV: return new Nodes.Binary(op, left, right) {
                @Override public double eval(EvalContext c) { return div(left.eval(c), right.eval(c)); } };
            default: return null;
        }
    }

    /** The node reading logical variable {@code which} ({@link Nodes.Var#TIME} …). */
    static Nodes.Var variable(int which) {
        switch (which) {
            case Nodes.Var.TIME: return new Nodes.Var(which) { @Override public double eval(EvalContext c) { return c.time; } };
            case Nodes.Var.BTIME: return new Nodes.Var(which) { @Override public double eval(EvalContext c) { return c.btime; } };
            case Nodes.Var.INDEX: return new Nodes.Var(which) { @Override public double eval(EvalContext c) { return c.index; } };
            case Nodes.Var.COUNT: return new Nodes.Var(which) { @Override public double eval(EvalContext c) { return c.count; } };
            case Nodes.Var.ID: return new Nodes.Var(which) { @Override public double eval(EvalContext c) { return c.id; } };
            case Nodes.Var.PHASE: return new Nodes.Var(which) { @Override public double eval(EvalContext c) { return c.phase; } };
            default: return new Nodes.Var(Nodes.Var.CYCLE) { @Override public double eval(EvalContext c) { return c.cycle; } };
        }
    }

    /** The specialised node for {@code f(arg)}, or null when the general one serves. */
    static Nodes.Func1 function(Functions.F1 f, Node arg) {
        switch (f) {
            case SIN: return new Nodes.Func1(f, arg) {
                @Override public double eval(EvalContext c) { double x = arg.eval(c); return checked(Math.sin(x), x); } };
            case COS: return new Nodes.Func1(f, arg) {
                @Override public double eval(EvalContext c) { double x = arg.eval(c); return checked(Math.cos(x), x); } };
            default: return null;
        }
    }
}
