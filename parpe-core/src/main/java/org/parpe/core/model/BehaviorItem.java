package org.parpe.core.model;

import org.parpe.core.diag.SourcePos;

/** A child of a behavior: an automaton instance or an {@code <if>} block. */
public sealed interface BehaviorItem permits Instance, Conditional {

    /** Where the item is written. */
    SourcePos pos();
}
