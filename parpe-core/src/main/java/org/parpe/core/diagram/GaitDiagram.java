package org.parpe.core.diagram;

import java.util.List;

/**
 * Which state each module is in over time (module × time, like Fig. 4 of the paper), as the
 * engine ran it: for each module the runs of ticks spent in one state of one instance.
 *
 * @param dt        the tick, seconds
 * @param ticks     the number of ticks recorded (tick 0 included)
 * @param moduleIds the rows: module IDs, ascending
 * @param segments  every run of ticks, by row then time
 * @param legend    per entry, per instance, the automaton's state names
 * @param entries   the behavior of each {@code <main>} entry, in order
 */
public record GaitDiagram(double dt, int ticks, int[] moduleIds, List<Segment> segments,
                          List<List<Instance>> legend, List<String> entries) {

    public GaitDiagram {
        moduleIds = moduleIds.clone();
        segments = List.copyOf(segments);
        legend = legend.stream().map(List::copyOf).toList();
        entries = List.copyOf(entries);
    }

    /**
     * The name a state is drawn with: {@code automaton.state}, or the state alone when it is
     * named after its automaton (a gait table's rows); {@code null} when there is no such state.
     */
    public String stateName(int entry, int instance, int state) {
        if (entry < 0 || entry >= legend.size() || instance < 0 || instance >= legend.get(entry).size()) {
            return null;
        }
        Instance in = legend.get(entry).get(instance);
        if (state < 0 || state >= in.states().size()) {
            return null;
        }
        String name = in.states().get(state);
        return name.startsWith(in.automaton() + "[") ? name : in.automaton() + "." + name;
    }

    /** Every state's {@link #stateName}, each once, in legend order (the order of the colours). */
    public List<String> stateNames() {
        java.util.LinkedHashSet<String> names = new java.util.LinkedHashSet<>();
        for (int e = 0; e < legend.size(); e++) {
            for (int i = 0; i < legend.get(e).size(); i++) {
                for (int s = 0; s < legend.get(e).get(i).states().size(); s++) {
                    names.add(stateName(e, i, s));
                }
            }
        }
        return List.copyOf(names);
    }

    /**
     * Ticks {@code [from, to)} during which the module of row {@code row} was in one state.
     *
     * @param row      the module's row
     * @param from     the first tick
     * @param to       just after the last tick
     * @param entry    the {@code <main>} entry that ran
     * @param instance the instance of that entry's behavior that drove the module
     * @param state    its state index
     */
    public record Segment(int row, int from, int to, int entry, int instance, int state) {
    }

    /**
     * An instance of an entry's behavior.
     *
     * @param automaton its automaton
     * @param states    the automaton's state names, in cycle order
     */
    public record Instance(String automaton, List<String> states) {

        public Instance {
            states = List.copyOf(states);
        }
    }
}
