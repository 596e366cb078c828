package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Expression;

/**
 * A state: target angles in degrees (PARSL.md §5), or one row of a gait table.
 *
 * @param name   the state's name ({@code travel[0]} for a gait-table row)
 * @param angles one expression for the whole group, or one per module position
 * @param interp  the motion profile
 * @param latch   the connection plates the module arms when it enters the state (PARSL.md §14), ascending
 * @param unlatch the connection plates the module releases when it enters the state, ascending
 * @param pos     the element (or the row)
 */
public record StateDef(String name, List<Expression> angles, Interp interp, List<Integer> latch,
                       List<Integer> unlatch, SourcePos pos) {

    public StateDef {
        angles = List.copyOf(angles);
        latch = List.copyOf(latch);
        unlatch = List.copyOf(unlatch);
    }

    /** A state without plate actions (every gait-table row is one, PARSL.md §14). */
    public StateDef(String name, List<Expression> angles, Interp interp, SourcePos pos) {
        this(name, angles, interp, List.of(), List.of(), pos);
    }

    /** Whether entering the state arms or releases a connection plate. */
    public boolean hasPlateActions() {
        return !latch.isEmpty() || !unlatch.isEmpty();
    }
}
