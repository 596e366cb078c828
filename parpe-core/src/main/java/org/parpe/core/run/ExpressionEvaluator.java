package org.parpe.core.run;

import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.EvalContext;
import org.parpe.core.expr.Expression;

/** Evaluates expressions for the scheduler, turning failures into located run-time errors. */
interface ExpressionEvaluator {
    /** The shared evaluation context. */
    EvalContext ctx();

    /** Evaluates {@code e}; a non-finite value becomes a {@link ScriptRuntimeError}. */
    double eval(Expression e);

    /** A run-time error at {@code pos} during the current tick. */
    ScriptRuntimeError error(SourcePos pos, org.parpe.core.text.Message message);

    /** A run-time error at {@code pos}: the text of {@code key} with {@code args}. */
    default ScriptRuntimeError error(SourcePos pos, org.parpe.core.text.Msg key, Object... args) {
        return error(pos, org.parpe.core.text.Message.of(key, args));
    }
}
