package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * One entry of {@code <sensors>}: modules that carry a sensor type.
 *
 * @param type     {@code angle}, {@code accel} or {@code touch}
 * @param modules  module IDs
 * @param elements the {@code elements} attribute as written
 * @param pos      the element
 */
public record SensorDecl(String type, List<Integer> modules, String elements, SourcePos pos) {

    public SensorDecl {
        modules = List.copyOf(modules);
    }
}
