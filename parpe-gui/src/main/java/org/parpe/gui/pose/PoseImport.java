package org.parpe.gui.pose;

import java.util.List;
import java.util.Optional;
import org.parpe.core.expr.Expression;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.BehaviorItem;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.Group;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;
import org.parpe.core.model.Timing;

/**
 * Reads poses back from a script: the first gait table that a behavior plays on a group (a
 * PARSL.md §12 recording, or any table of plain numbers), one pose per row with its row time as
 * the time since the previous pose. Tables whose angles or times are expressions are skipped.
 */
final class PoseImport {
    private PoseImport() {
    }

    /** The poses of the first table played on {@code group} (or on any group when null), or empty. */
    static Optional<PoseList> read(Program program, String group) {
        for (Behavior b : program.behaviors()) {
            Optional<PoseList> found = read(program, group, b.items());
            if (found.isPresent()) {
                return found;
            }
        }
        return Optional.empty();
    }

    private static Optional<PoseList> read(Program program, String group, List<BehaviorItem> items) {
        for (BehaviorItem item : items) {
            if (item instanceof Conditional c) {
                Optional<PoseList> found = read(program, group, c.items());
                if (found.isPresent()) {
                    return found;
                }
            } else if (item instanceof Instance i && (group == null || i.group().equals(group))) {
                Group g = i.groupRef().mirror() ? null : i.on();
                Automaton a = i.automaton();
                if (g != null && a != null && a.table()) {
                    Optional<PoseList> l = table(g, a);
                    if (l.isPresent()) {
                        return l;
                    }
                }
            }
        }
        return Optional.empty();
    }

    private static Optional<PoseList> table(Group g, Automaton a) {
        int[] modules = g.modules().stream().mapToInt(Integer::intValue).toArray();
        PoseList list = new PoseList(g.name(), modules);
        for (int r = 0; r < a.states().size(); r++) {
            StateDef row = a.states().get(r);
            Timing t = a.times().get(r);
            if (!t.duration().isConstant() || t.exit() != null) {
                return Optional.empty();
            }
            double[] angles = new double[modules.length];
            for (int k = 0; k < modules.length; k++) {
                Expression e = row.angles().get(row.angles().size() == 1 ? 0 : k);
                if (!e.isConstant()) {
                    return Optional.empty();
                }
                angles[k] = e.eval(null);
            }
            try {
                list.add(angles, t.duration().eval(null));
            } catch (IllegalArgumentException outOfRange) {
                return Optional.empty();
            }
        }
        return list.size() == 0 ? Optional.empty() : Optional.of(list);
    }
}
