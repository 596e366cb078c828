package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;

/**
 * One entry of {@code <actuators>}: modules that carry an actuator type (PARSL.md §2; the one
 * type is {@code latch}, the connection plates' latches of §14).
 *
 * @param type     {@code latch}
 * @param modules  module IDs
 * @param elements the {@code elements} attribute as written
 * @param pos      the element
 */
public record ActuatorDecl(String type, List<Integer> modules, String elements, SourcePos pos) {

    public ActuatorDecl {
        modules = List.copyOf(modules);
    }
}
