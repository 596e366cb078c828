package org.parpe.core.model;

import java.util.List;
import java.util.Optional;
import org.parpe.core.diag.SourcePos;

/**
 * The {@code <robot>} section: named groups (the implicit {@code all} included, last, unless
 * the script defines it), the set of modules, and sensor declarations.
 *
 * @param groups  groups in document order, then {@code all} if implicit
 * @param modules every module ID named in {@code <structure>}, ascending
 * @param sensors sensor declarations in document order
 * @param actuators actuator declarations in document order
 * @param file    the robot file when given by {@code <robot file>}, else empty
 * @param pos     the {@code <robot>} element
 */
public record Robot(List<Group> groups, List<Integer> modules, List<SensorDecl> sensors,
                    List<ActuatorDecl> actuators, String file, SourcePos pos) {

    public Robot {
        groups = List.copyOf(groups);
        modules = List.copyOf(modules);
        sensors = List.copyOf(sensors);
        actuators = List.copyOf(actuators);
    }

    /** The module IDs as a fresh array, ascending. */
    public int[] moduleIds() {
        return modules.stream().mapToInt(Integer::intValue).toArray();
    }

    /** The group called {@code name}. */
    public Optional<Group> group(String name) {
        return groups.stream().filter(g -> g.name().equals(name)).findFirst();
    }

    /** Whether module {@code id} carries sensor type {@code type}. */
    public boolean carries(int id, String type) {
        return sensors.stream().anyMatch(s -> s.type().equals(type) && s.modules().contains(id));
    }

    /** Whether module {@code id} carries actuator type {@code type}. */
    public boolean actuates(int id, String type) {
        return actuators.stream().anyMatch(a -> a.type().equals(type) && a.modules().contains(id));
    }
}
