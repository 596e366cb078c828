package org.parpe.core.diagram;

import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * The {@code <main>} sequence as a lane of steps.
 *
 * @param cycles the {@code cycles} attribute as written, or {@code "1"} when absent
 * @param steps  the entries in order
 * @param pos    the {@code <main>} element
 */
public record ProgramLane(String cycles, List<Step> steps, SourcePos pos) {

    public ProgramLane {
        steps = List.copyOf(steps);
    }

    /**
     * One entry: a behavior with its run time and exit condition.
     *
     * @param index    the entry's position in {@code <main>}
     * @param behavior the behavior invoked
     * @param time     the {@code time} expression as written, or {@code null}
     * @param exit     the {@code exit} condition as written, or {@code null}
     * @param dock     the {@code dock} readings the exit condition waits on, in words, or empty (PARSL.md §14)
     * @param macros   each macro value as {@code name=value}, in the behavior's order
     * @param pos      the entry's element
     */
    public record Step(int index, String behavior, String time, String exit, String dock, List<String> macros,
                       SourcePos pos) {

        public Step {
            macros = List.copyOf(macros);
        }
    }
}
