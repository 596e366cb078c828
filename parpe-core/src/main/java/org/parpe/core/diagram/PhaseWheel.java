package org.parpe.core.diagram;

import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * The phases of one instance's modules on a wheel: module {@code i} of the group has the phase
 * delay {@code offset + i·phase} cycles (PARSL.md §7.1), drawn as a tick at that fraction of the
 * circle.
 *
 * @param automaton the instance's automaton
 * @param group     the group as written (with {@code !})
 * @param phase     the {@code phase} value in cycles (0 when absent)
 * @param offset    the {@code offset} value in cycles (0 when absent)
 * @param ticks     one tick per module, in group order
 * @param islands   what the wheel cannot show (a phase or offset that is not a constant)
 * @param pos       the instance's element
 */
public record PhaseWheel(String automaton, String group, double phase, double offset, List<Tick> ticks,
                         List<TextIsland> islands, SourcePos pos) {

    public PhaseWheel {
        ticks = List.copyOf(ticks);
        islands = List.copyOf(islands);
    }

    /** This wheel with phase {@code p}: each tick moved to {@code offset + position·p}, reduced to [0, 1). */
    public PhaseWheel withPhase(double p) {
        List<Tick> moved = new java.util.ArrayList<>();
        for (Tick t : ticks) {
            double d = offset + t.position() * p;
            moved.add(new Tick(t.position(), t.module(), d - Math.floor(d)));
        }
        return new PhaseWheel(automaton, group, p, offset, moved, islands, pos);
    }

    /**
     * One module.
     *
     * @param position the module's position in the group
     * @param module   its ID
     * @param delay    its phase delay {@code offset + position·phase}, reduced to [0, 1)
     */
    public record Tick(int position, int module, double delay) {
    }
}
