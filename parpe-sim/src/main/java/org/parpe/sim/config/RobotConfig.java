package org.parpe.sim.config;

import java.util.List;
import java.util.Optional;

/**
 * Simulated robots: parts, how their plates are connected, the initial pose. Immutable; made
 * by {@link RobotConfigs} from a generator spec or a configuration file. Most configurations
 * are one robot (one root); a configuration with several roots holds several robots, one per
 * root, that docking (PARSL.md §14) may join during a run.
 *
 * @param name        a name for messages (the generator spec or the file)
 * @param parts       parts in definition order
 * @param connections connections in definition order; a connection between parts that are
 *                    already joined through others closes a loop
 * @param roots       where each robot's root part goes, at least one; the first is the root of
 *                    the whole (what progress and falls are judged by)
 */
public record RobotConfig(String name, List<PartSpec> parts, List<Connection> connections,
                          List<RootPose> roots) {

    public RobotConfig {
        parts = List.copyOf(parts);
        connections = List.copyOf(connections);
        roots = List.copyOf(roots);
        if (roots.isEmpty()) {
            throw new IllegalArgumentException("a configuration needs a root");
        }
    }

    /** One robot with its root part at {@code root}. */
    public RobotConfig(String name, List<PartSpec> parts, List<Connection> connections, RootPose root) {
        this(name, parts, connections, List.of(root));
    }

    /** The first root: where the (first) robot's root part goes. */
    public RootPose root() {
        return roots.get(0);
    }

    /** The part called {@code partName}. */
    public Optional<PartSpec> part(String partName) {
        return parts.stream().filter(p -> p.name().equals(partName)).findFirst();
    }

    /** The logical IDs of every segment, ascending. */
    public int[] moduleIds() {
        return parts.stream().filter(PartSpec::isSegment).mapToInt(PartSpec::moduleId).sorted().toArray();
    }
}
