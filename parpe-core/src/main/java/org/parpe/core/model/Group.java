package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * A named, ordered list of modules.
 *
 * @param name     the group's name
 * @param modules  module IDs in group order
 * @param elements the {@code elements} attribute as written (empty for the implicit {@code all})
 * @param implicit whether this is the predefined {@code all}
 * @param pos      the defining element
 */
public record Group(String name, List<Integer> modules, String elements, boolean implicit,
                    SourcePos pos) {

    public Group {
        modules = List.copyOf(modules);
    }

    /** Number of modules. */
    public int size() {
        return modules.size();
    }
}
