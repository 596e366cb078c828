package org.parpe.core.model;

import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Expression;

/**
 * An automaton applied to a group inside a behavior (PARSL.md §7), bound at load: it holds the
 * automaton itself and, unless its group is a macro, the group, so no later stage looks a name
 * up again. Optional attributes are {@code null} when absent.
 *
 * @param automaton the automaton it plays (its element's name is the automaton's name)
 * @param group     the {@code group} attribute as written: a group or macro name, maybe with {@code !}
 * @param on        the group it names, or {@code null} when it names a group macro (each {@code <main>}
 *                  entry binds that: {@link MainEntry.Binding})
 * @param phase     phase delay between successive modules, cycles
 * @param offset    phase delay of the whole group, cycles
 * @param period    seconds per cycle
 * @param start     seconds after the behavior starts
 * @param cycles    number of cycles to run
 * @param pos       the element
 */
public record Instance(Automaton automaton, String group, Group on, Expression phase, Expression offset,
                       Expression period, Expression start, Expression cycles, SourcePos pos)
        implements BehaviorItem {

    /** The {@code group} attribute read: the group or macro name and whether it has {@code !}. */
    public MainEntry.GroupRef groupRef() {
        return MainEntry.GroupRef.parse(group);
    }

    /** The automaton's name, which is the instance element's name. */
    public String name() {
        return automaton.name();
    }
}
