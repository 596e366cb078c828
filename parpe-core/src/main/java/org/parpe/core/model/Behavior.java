package org.parpe.core.model;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * A behavior: automaton instances that run in parallel (PARSL.md §7).
 *
 * @param name   the name
 * @param macros macro names, in declaration order
 * @param items  instances and conditional blocks in document order
 * @param pos    the element
 */
public record Behavior(String name, List<String> macros, List<BehaviorItem> items, SourcePos pos) {

    public Behavior {
        macros = List.copyOf(macros);
        items = List.copyOf(items);
    }

    /** Every instance, depth first in document order. */
    public List<Instance> instances() {
        List<Instance> out = new ArrayList<>();
        collect(items, out);
        return out;
    }

    private static void collect(List<BehaviorItem> items, List<Instance> out) {
        for (BehaviorItem item : items) {
            if (item instanceof Instance) {
                out.add((Instance) item);
            } else {
                collect(((Conditional) item).items(), out);
            }
        }
    }
}
