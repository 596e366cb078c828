package org.parpe.core.expr;

/** A node of a compiled expression tree. Evaluation must not allocate. */
public abstract class Node {
    /** Evaluates the node. */
    public abstract double eval(EvalContext ctx);
}
