package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * A phase automaton or a gait table (PARSL.md §6).
 *
 * @param name       the name
 * @param states     the states in cycle order (gait-table rows are anonymous states)
 * @param times      one timing per state (default 1 s each when {@code times} is absent)
 * @param table      whether this is a gait table
 * @param timesText  the {@code times} attribute as written, or {@code null} if absent
 * @param pos        the element
 */
public record Automaton(String name, List<StateDef> states, List<Timing> times, boolean table,
                        String timesText, SourcePos pos) {

    public Automaton {
        states = List.copyOf(states);
        times = List.copyOf(times);
    }
}
