/**
 * PARSL expressions: compilation on exp4j's parser to allocation-free node trees, scopes and
 * the evaluation context (public API: {@link org.parpe.core.expr.Expression},
 * {@link org.parpe.core.expr.EvalContext}, {@link org.parpe.core.expr.ExprCompiler}).
 */
package org.parpe.core.expr;
