package org.parpe.core.expr;

import java.util.Map;
import java.util.Set;
import org.parpe.core.sensor.Channel;

/**
 * What names an expression may use where it is written (PARSL.md §13 rule 12), and how they
 * resolve. Built by the loader; immutable.
 *
 * @param kind          where the expression is, for messages and rules
 * @param parameters    parameter values by name (folded to constants)
 * @param controls      control index by name (only where controls are visible)
 * @param radioWords    radio word codes (only where controls are visible)
 * @param groups        group names (to explain misuse)
 * @param macros        expression-valued macros of the behavior: name → index
 * @param groupMacros   group-valued macros of the behavior (to explain misuse)
 * @param sensors       the sensors of the robot, for global references (null where not visible)
 */
public record Scope(Kind kind, Map<String, Double> parameters, Map<String, Integer> controls,
                    Map<String, Integer> radioWords, Set<String> groups,
                    Map<String, Integer> macros, Set<String> groupMacros, SensorCatalog sensors) {

    /** The places expressions can appear, each with its own visible names. */
    public enum Kind {
        /** Group ranges and {@code <main cycles>}: parameters only. */
        PARAMETERS_ONLY,
        /** {@code <main>} entry {@code time}, {@code exit} and macro values. */
        ENTRY,
        /** Instance attributes ({@code phase}, {@code period}, …): adds macros and {@code $count}. */
        INSTANCE,
        /** {@code <if cond>}: adds macros. */
        CONDITION,
        /** States and automaton {@code times}: the current module is known. */
        MODULE
    }

    /** Knows which module carries which sensor and where its readings live. */
    public interface SensorCatalog {
        /** A robot without sensors. */
        SensorCatalog NONE = new SensorCatalog() {
            @Override
            public int moduleIndex(int id) {
                return -1;
            }

            @Override
            public boolean carries(int id, Channel channel) {
                return false;
            }
        };

        /** The sensor-table index of module {@code id}, or −1 if it is not in the robot. */
        int moduleIndex(int id);

        /** Whether module {@code id} carries the sensor type of {@code channel}. */
        boolean carries(int id, Channel channel);
    }

    boolean sees(String logical) {
        switch (logical) {
            case "time": case "btime": return kind != Kind.PARAMETERS_ONLY;
            case "count": return kind == Kind.INSTANCE || kind == Kind.MODULE;
            case "index": case "id": case "phase": case "cycle": return kind == Kind.MODULE;
            default: return false;
        }
    }
}
