package org.parpe.core.diagram;

import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * A behavior as swimlanes: one lane per group an instance drives, each instance a bar.
 *
 * @param behavior the behavior
 * @param entry    the {@code <main>} entry whose macro values resolve macro groups, or −1
 * @param lanes    the lanes, in the order their groups first appear
 * @param islands  what the lanes cannot show
 * @param pos      the behavior's element
 */
public record Swimlanes(String behavior, int entry, List<Lane> lanes, List<TextIsland> islands, SourcePos pos) {

    public Swimlanes {
        lanes = List.copyOf(lanes);
        islands = List.copyOf(islands);
    }

    /**
     * The instances on one group.
     *
     * @param group    the group's name (a macro's value resolved), without {@code !}
     * @param modules  its module IDs in group order; empty for an unresolved macro group
     * @param bars     the instances driving it, in document order
     */
    public record Lane(String group, List<Integer> modules, List<Bar> bars) {

        public Lane {
            modules = List.copyOf(modules);
            bars = List.copyOf(bars);
        }
    }

    /**
     * One automaton instance. Attribute texts are as written, {@code null} when absent.
     *
     * @param index      the instance's position in the behavior, depth first in document order
     * @param automaton  the automaton
     * @param mirrored   whether the group is mirrored ({@code !}, after macro resolution)
     * @param phase      the {@code phase} attribute
     * @param offset     the {@code offset} attribute
     * @param period     the {@code period} attribute
     * @param start      the {@code start} attribute
     * @param cycles     the {@code cycles} attribute
     * @param conditions the conditions of the enclosing {@code <if>} blocks, outermost first
     * @param overlaps   the other instances ({@link #index}) that share a module with this one:
     *                   they may drive one module twice (only possible under {@code <if>})
     * @param shared     a module this one shares with the first of {@code overlaps}, or −1
     * @param pos        the instance's element
     */
    public record Bar(int index, String automaton, boolean mirrored, String phase, String offset, String period,
                      String start, String cycles, List<String> conditions, List<Integer> overlaps, int shared,
                      SourcePos pos) {

        public Bar {
            conditions = List.copyOf(conditions);
            overlaps = List.copyOf(overlaps);
        }
    }
}
