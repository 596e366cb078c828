package org.parpe.core.run;

import java.util.Arrays;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.MainEntry;

/**
 * One {@code <main>} entry made ready to run: its instances, whose groups, automata and mirror
 * flags the loader resolved ({@link MainEntry#bindings()}), with module slots and macro slots.
 */
final class EntryPlan {
    final MainEntry entry;
    final Behavior behavior;
    final InstanceRun[] runs;
    final double[] macros;
    /** Expression-valued macro arguments and their slots, evaluated when the entry starts. */
    final MainEntry.MacroArg[] valueArgs;
    final int[] valueSlots;

    EntryPlan(MainEntry entry, int[] moduleIds) {
        this.entry = entry;
        this.behavior = entry.definition();
        this.macros = new double[behavior.macros().size()];
        this.valueArgs = entry.macros().stream().filter(a -> a.value() != null).toArray(MainEntry.MacroArg[]::new);
        this.valueSlots = new int[valueArgs.length];
        for (int i = 0; i < valueArgs.length; i++) {
            valueSlots[i] = behavior.macros().indexOf(valueArgs[i].name());
        }
        this.runs = new InstanceRun[entry.bindings().size()];
        for (int r = 0; r < runs.length; r++) {
            MainEntry.Binding b = entry.bindings().get(r);
            int[] ids = b.group().modules().stream().mapToInt(Integer::intValue).toArray();
            int[] mod = new int[ids.length];
            for (int k = 0; k < ids.length; k++) {
                mod[k] = Arrays.binarySearch(moduleIds, ids[k]);
            }
            runs[r] = new InstanceRun(b.instance(), b.automaton(), b.conditions().toArray(new Conditional[0]), r, mod,
                    ids, b.mirrored());
        }
    }
}
