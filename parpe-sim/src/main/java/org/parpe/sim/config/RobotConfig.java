package org.parpe.sim.config;

import java.util.List;
import java.util.Optional;

/**
 * A simulated robot: parts, how their plates are connected, the initial pose. Immutable; made
 * by {@link RobotConfigs} from a generator spec or a configuration file.
 *
 * @param name        a name for messages (the generator spec or the file)
 * @param parts       parts in definition order
 * @param connections connections in definition order; a connection between parts that are
 *                    already joined through others closes a loop
 * @param root        where the root part goes
 */
public record RobotConfig(String name, List<PartSpec> parts, List<Connection> connections,
                          RootPose root) {

    public RobotConfig {
        parts = List.copyOf(parts);
        connections = List.copyOf(connections);
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
