package org.parpe.gui.grid;

import java.util.List;
import org.parpe.core.model.BehaviorItem;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Program;

/** The modules a gait table drives: those of the first group it is applied to in the behaviors. */
final class Modules {
    private Modules() {
    }

    /** The module IDs of the group {@code automaton} first runs on, or {@code null} if it is used nowhere. */
    static List<Integer> of(Program p, String automaton) {
        if (p == null) {
            return null;
        }
        for (var b : p.behaviors()) {
            List<Integer> m = in(b.items(), automaton);
            if (m != null) {
                return m;
            }
        }
        return null;
    }

    /**
     * The seconds each row of the table {@code automaton} lasts when the rows share the period
     * equally (no {@code times}): the constant period of the first instance that plays it over
     * {@code rows}, or null when it is played nowhere or with a period that changes.
     */
    static Double secondsPerRow(Program p, String automaton, int rows) {
        if (p == null || rows <= 0) {
            return null;
        }
        for (var b : p.behaviors()) {
            Instance i = instance(b.items(), automaton);
            if (i != null) {
                return i.period() != null && i.period().isConstant() ? i.period().eval(null) / rows : null;
            }
        }
        return null;
    }

    private static Instance instance(List<BehaviorItem> items, String automaton) {
        for (BehaviorItem item : items) {
            if (item instanceof Instance i && i.name().equals(automaton)) {
                return i;
            } else if (item instanceof Conditional c) {
                Instance i = instance(c.items(), automaton);
                if (i != null) {
                    return i;
                }
            }
        }
        return null;
    }

    private static List<Integer> in(List<BehaviorItem> items, String automaton) {
        for (BehaviorItem item : items) {
            if (item instanceof Instance i && i.name().equals(automaton)) {
                // the group bound at load; a mirrored or macro group gives no modules here, as before
                List<Integer> m = i.on() == null || i.groupRef().mirror() ? null : i.on().modules();
                if (m != null) {
                    return m;
                }
            } else if (item instanceof Conditional c) {
                List<Integer> m = in(c.items(), automaton);
                if (m != null) {
                    return m;
                }
            }
        }
        return null;
    }
}
