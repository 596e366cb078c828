package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;

/**
 * Records a {@link GaitDiagram} by running the program's own {@link Engine} headless and asking
 * it at every tick which state each module is in: the diagram shows what the scheduler does,
 * not a second model of it.
 */
public final class Gait {
    private Gait() {
    }

    /**
     * Runs {@code p} with {@code options} for {@code duration} seconds (or until {@code <main>}
     * ends) and records each module's state at every tick.
     *
     * @throws org.parpe.core.run.ScriptRuntimeError when the script fails at run time
     */
    public static GaitDiagram record(Program p, RunOptions options, double duration) {
        Engine e = new Engine(p, options);
        int[] ids = e.moduleIds();
        int n = ids.length;
        int[] inst = new int[n];
        int[] state = new int[n];
        int[] runEntry = new int[n];
        int[] runInst = new int[n];
        int[] runState = new int[n];
        int[] runFrom = new int[n];
        java.util.Arrays.fill(runInst, -1);
        List<List<GaitDiagram.Segment>> rows = new ArrayList<>();
        for (int m = 0; m < n; m++) {
            rows.add(new ArrayList<>());
        }
        e.start();
        int tick = 0;
        long last = Math.round(duration / options.dt());
        boolean going = true;
        while (going && tick <= last) {
            going = e.step();
            int entry = e.status().entryIndex();
            e.moduleStates(inst, state);
            for (int m = 0; m < n; m++) {
                if (inst[m] != runInst[m] || state[m] != runState[m] || entry != runEntry[m]) {
                    close(rows.get(m), m, runFrom[m], tick, runEntry[m], runInst[m], runState[m]);
                    runFrom[m] = tick;
                    runEntry[m] = entry;
                    runInst[m] = inst[m];
                    runState[m] = state[m];
                }
            }
            tick++;
        }
        List<GaitDiagram.Segment> all = new ArrayList<>();
        for (int m = 0; m < n; m++) {
            close(rows.get(m), m, runFrom[m], tick, runEntry[m], runInst[m], runState[m]);
            all.addAll(rows.get(m));
        }
        return new GaitDiagram(options.dt(), tick, ids, all, legend(p), entries(p));
    }

    private static void close(List<GaitDiagram.Segment> row, int m, int from, int to, int entry, int inst, int state) {
        if (inst >= 0 && to > from) {
            row.add(new GaitDiagram.Segment(m, from, to, entry, inst, state));
        }
    }

    private static List<String> entries(Program p) {
        return p.main() == null ? List.of() : p.main().entries().stream().map(MainEntry::behavior).toList();
    }

    private static List<List<GaitDiagram.Instance>> legend(Program p) {
        List<List<GaitDiagram.Instance>> out = new ArrayList<>();
        for (MainEntry e : p.main() == null ? List.<MainEntry>of() : p.main().entries()) {
            Behavior b = e.definition();
            List<GaitDiagram.Instance> list = new ArrayList<>();
            for (Instance i : b.instances()) {
                List<String> states = i.automaton().states().stream().map(StateDef::name).toList();
                list.add(new GaitDiagram.Instance(i.name(), states));
            }
            out.add(list);
        }
        return out;
    }
}
