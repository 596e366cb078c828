package org.parpe.core.run;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.BehaviorItem;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.Group;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Program;

/** One {@code <main>} entry made ready to run: its instances with groups resolved and macro slots. */
final class EntryPlan {
    final MainEntry entry;
    final Behavior behavior;
    final InstanceRun[] runs;
    final double[] macros;
    /** Expression-valued macro arguments and their slots, evaluated when the entry starts. */
    final MainEntry.MacroArg[] valueArgs;
    final int[] valueSlots;

    EntryPlan(Program program, MainEntry entry, int[] moduleIds) {
        this.entry = entry;
        this.behavior = program.behavior(entry.behavior()).orElseThrow();
        this.macros = new double[behavior.macros().size()];
        this.valueArgs = entry.macros().stream().filter(a -> a.value() != null).toArray(MainEntry.MacroArg[]::new);
        this.valueSlots = new int[valueArgs.length];
        for (int i = 0; i < valueArgs.length; i++) {
            valueSlots[i] = behavior.macros().indexOf(valueArgs[i].name());
        }
        List<InstanceRun> list = new ArrayList<>();
        collect(program, behavior.items(), new ArrayList<>(), list, moduleIds);
        this.runs = list.toArray(new InstanceRun[0]);
    }

    private void collect(Program program, List<BehaviorItem> items, List<Conditional> conds, List<InstanceRun> out,
                         int[] moduleIds) {
        for (BehaviorItem item : items) {
            if (item instanceof Conditional) {
                Conditional c = (Conditional) item;
                conds.add(c);
                collect(program, c.items(), conds, out, moduleIds);
                conds.remove(conds.size() - 1);
                continue;
            }
            Instance i = (Instance) item;
            MainEntry.GroupRef ref = entry.groupOf(i);
            boolean mirror = ref.mirror();
            Group group = program.group(ref.name()).orElseThrow();
            int[] ids = group.modules().stream().mapToInt(Integer::intValue).toArray();
            int[] mod = new int[ids.length];
            for (int k = 0; k < ids.length; k++) {
                mod[k] = Arrays.binarySearch(moduleIds, ids[k]);
            }
            Automaton a = program.automaton(i.automaton()).orElseThrow();
            out.add(new InstanceRun(i, a, conds.toArray(new Conditional[0]), out.size(), mod, ids, mirror));
        }
    }
}
