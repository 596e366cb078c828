package org.parpe.core.expr;

import org.parpe.core.diag.SourcePos;

/**
 * A compiled PARSL expression with its source text and place. Compiled once at load, it is
 * evaluated per tick against an {@link EvalContext} without allocating. Two expressions are
 * equal when their source text is equal (positions are not compared), so that models can be
 * compared across a print/parse round trip.
 */
public final class Expression {
    private final String text;
    private final SourcePos pos;
    private final Node root;
    private final boolean perModule;

    /** Wraps a compiled tree; {@code perModule} if it reads the current module's variables or sensors. */
    public Expression(String text, SourcePos pos, Node root, boolean perModule) {
        this.text = text;
        this.pos = pos;
        this.root = root;
        this.perModule = perModule;
    }

    /** A constant expression (used for defaults). */
    public static Expression constant(double value, String text) {
        return new Expression(text, SourcePos.NONE, new Nodes.Const(value), false);
    }

    /** The expression as written in the script (after XML decoding). */
    public String text() {
        return text;
    }

    /** Where the expression starts in the source. */
    public SourcePos pos() {
        return pos;
    }

    /**
     * Evaluates the expression.
     *
     * @throws EvalException if a value is not finite (division by zero, {@code log(0)}, …)
     */
    public double eval(EvalContext ctx) {
        return root.eval(ctx);
    }

    /**
     * This expression as seen by the module at position {@code index} of a group of
     * {@code count} modules whose ID is {@code id}: those three variables replaced by their
     * values and the parts that then depend on nothing else computed, with the same text and
     * place (for messages); this expression itself when it reads none of them. The result
     * evaluates to the same value as this expression with the context entered for that module,
     * bit for bit, and fails where and as this one does.
     */
    public Expression bind(int index, int count, int id) {
        Node bound = ModuleBinding.bind(root, index, count, id);
        return bound == root ? this : new Expression(text, pos, bound, perModule);
    }

    /** Whether the value does not depend on anything that changes during a run. */
    public boolean isConstant() {
        return root instanceof Nodes.Const;
    }

    /** Whether the value depends on the current module ($index, $id, $phase, $cycle, local sensors). */
    public boolean perModule() {
        return perModule;
    }

    /** The compiled tree. */
    public Node root() {
        return root;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Expression && ((Expression) o).text.equals(text);
    }

    @Override
    public int hashCode() {
        return text.hashCode();
    }

    @Override
    public String toString() {
        return text;
    }
}
