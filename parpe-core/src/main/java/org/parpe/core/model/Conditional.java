package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Expression;

/**
 * An {@code <if cond="C">} block: its items run only while {@code C} holds.
 *
 * @param condition the condition
 * @param items     nested instances and blocks
 * @param pos       the element
 */
public record Conditional(Expression condition, List<BehaviorItem> items, SourcePos pos)
        implements BehaviorItem {

    public Conditional {
        items = List.copyOf(items);
    }
}
