package org.parpe.core.diagram;

import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * An automaton as a ring: its states around a circle in cycle order, each an arc whose length
 * is proportional to its duration {@code T_i}.
 *
 * @param automaton the automaton
 * @param table     whether it is a gait table (its rows are the states)
 * @param group     the group its states are posed on (the first it is played on, {@code !} when
 *                  mirrored), or {@code null} when no behavior plays it
 * @param modules   that group's size (0 without a group)
 * @param arcs      one arc per state, in cycle order, together covering the circle
 * @param islands   what the ring cannot show (durations it had to estimate)
 * @param pos       the automaton's element
 */
public record Ring(String automaton, boolean table, String group, int modules, List<Arc> arcs, List<TextIsland> islands, SourcePos pos) {

    public Ring {
        arcs = List.copyOf(arcs);
        islands = List.copyOf(islands);
    }

    /**
     * One state.
     *
     * @param index    the state's position in the cycle
     * @param state    its name
     * @param duration its duration as written
     * @param exit     its exit condition as written, or {@code null}
     * @param angles   its target angles as written (one for the whole group, or one per module)
     * @param pose     its angles in degrees on the first {@link Diagrams#POSE_MODULES} modules of
     *                 {@code group}, or empty when they are known only while running
     * @param seconds  its duration in seconds, or {@code NaN} when it is not a constant
     * @param plates   what entering it does to the connection plates (PARSL.md §14) in words, or empty
     * @param dock     the {@code dock} readings its exit condition waits on, in words, or empty (§14)
     * @param from     where the arc starts, as a fraction of the circle (0 at the top, clockwise)
     * @param to       where it ends
     * @param pos      the state's definition
     */
    public record Arc(int index, String state, String duration, String exit, List<String> angles, List<Double> pose,
                      double seconds, String plates, String dock,
                      double from, double to, SourcePos pos) {

        public Arc {
            angles = List.copyOf(angles);
            pose = List.copyOf(pose);
        }
    }
}
