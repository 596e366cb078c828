package org.parpe.sim.build;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.parpe.core.model.Group;
import org.parpe.core.model.Program;
import org.parpe.sim.config.RobotConfig;

/**
 * How a robot fits a script: the script's modules the robot lacks (their commands would be
 * ignored), the robot's modules no group of the script uses (they would stand still), and the
 * group each module belongs to (a builder colours parts by it).
 *
 * @param missing module IDs of the script that no segment of the robot has, ascending
 * @param unused  module IDs of the robot's segments that no group of the script holds, ascending
 * @param groupOf for each module of the script, the first group in document order that holds
 *                it (the implicit {@code all} only for a module no named group holds)
 */
public record ScriptFit(List<Integer> missing, List<Integer> unused, Map<Integer, String> groupOf) {

    public ScriptFit {
        missing = List.copyOf(missing);
        unused = List.copyOf(unused);
        groupOf = Collections.unmodifiableMap(new TreeMap<>(groupOf));
    }

    /** How robot {@code c} fits script {@code p}. */
    public static ScriptFit of(Program p, RobotConfig c) {
        Map<Integer, String> groupOf = new TreeMap<>();
        for (Group g : p.robot().groups()) {
            if (!g.implicit()) {
                g.modules().forEach(m -> groupOf.putIfAbsent(m, g.name()));
            }
        }
        for (Group g : p.robot().groups()) {
            if (g.implicit()) {
                g.modules().forEach(m -> groupOf.putIfAbsent(m, g.name()));
            }
        }
        int[] have = c.moduleIds();
        List<Integer> missing = new ArrayList<>();
        for (int id : p.moduleIds()) {
            if (Arrays.binarySearch(have, id) < 0) {
                missing.add(id);
            }
        }
        missing.sort(null);
        List<Integer> unused = new ArrayList<>();
        for (int id : have) {
            if (!groupOf.containsKey(id)) {
                unused.add(id);
            }
        }
        return new ScriptFit(missing, unused, groupOf);
    }
}
