package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Expression;

/**
 * A state: target angles in degrees (PARSL.md §5), or one row of a gait table.
 *
 * @param name   the state's name ({@code travel[0]} for a gait-table row)
 * @param angles one expression for the whole group, or one per module position
 * @param interp the motion profile
 * @param pos    the element (or the row)
 */
public record StateDef(String name, List<Expression> angles, Interp interp, SourcePos pos) {

    public StateDef {
        angles = List.copyOf(angles);
    }
}
