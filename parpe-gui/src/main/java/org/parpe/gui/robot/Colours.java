package org.parpe.gui.robot;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.model.Program;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.build.RobotDraft;
import org.parpe.sim.build.ScriptFit;
import org.parpe.sim.config.Kit;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.PartType;

/**
 * How the Robot tab marks a robot for a script: parts in the colours of the script's groups,
 * parts at fault red, the plates of modules that declare the {@code latch} actuator (PARSL.md
 * §14) marked; and the line that says what the script misses, what it leaves unused and what
 * the kit has left.
 */
final class Colours {
    /** One colour per group, in the order the groups are first met (then again from the start). */
    private static final int[] GROUPS = {0x2E9E5B, 0x8E5CC8, 0xD9822B, 0x2B8FD9, 0xC2477D, 0x6B8E23, 0x7A6A56, 0x1F9FA0};

    private Colours() {
    }

    /** Sets {@code t}'s colours and latch marks for draft {@code d} and the script {@code script} (may be null). */
    static void paint(Targets t, RobotDraft d, Program script, boolean showFaults) {
        Map<String, Integer> paint = new HashMap<>();
        Set<String> latching = new TreeSet<>();
        if (d != null && d.config() != null) {
            List<PartSpec> parts = d.config().parts();
            if (script != null) {
                Map<Integer, String> groupOf = ScriptFit.of(script, d.config()).groupOf();
                Map<String, Integer> groupColour = new LinkedHashMap<>();
                for (PartSpec p : parts) {
                    String g = p.isSegment() ? groupOf.get(p.moduleId()) : null;
                    if (g != null) {
                        paint.put(p.name(), groupColour.computeIfAbsent(g, k -> GROUPS[groupColour.size() % GROUPS.length]));
                    }
                    if (p.isSegment() && script.robot().actuates(p.moduleId(), "latch")) {
                        latching.add(p.name());
                    }
                }
            }
            if (showFaults) {
                for (Diagnostic g : d.problems()) {
                    d.partAt(g.pos()).ifPresent(name -> paint.put(name, Targets.FAULT)); // the part the problem is about
                }
            }
        }
        t.paint = paint;
        t.latching = latching;
    }

    /** What the robot lacks for the script and leaves unused, what the kit has left, and the first problem. */
    static String fit(RobotDraft d, Program script, Kit kit) {
        if (d == null) {
            return "";
        }
        StringBuilder s = new StringBuilder();
        if (d.config() == null) {
            List<Diagnostic> p = d.problems();
            return p.isEmpty() ? "" : (p.size() == 1 ? ToolMsg.ROBOT_ONE_PROBLEM : ToolMsg.ROBOT_N_PROBLEMS).text(p.size(), p.get(0).format());
        }
        if (script != null) {
            ScriptFit f = ScriptFit.of(script, d.config());
            s.append(ToolMsg.ROBOT_SCRIPT_FIT.text(java.nio.file.Path.of(script.file()).getFileName(),
                    f.missing().isEmpty() && f.unused().isEmpty() ? ToolMsg.ROBOT_FIT_ALL.text()
                    : (f.missing().isEmpty() ? "" : ToolMsg.ROBOT_LACKS_MODULES.text(ids(f.missing())))
                    + (!f.missing().isEmpty() && !f.unused().isEmpty() ? "; " : "")
                    + (f.unused().isEmpty() ? "" : ToolMsg.ROBOT_UNUSED_MODULES.text(ids(f.unused())))));
        }
        if (kit != null) {
            Map<PartType, Integer> left = d.left(kit);
            s.append(s.length() == 0 ? "" : "   ").append(ToolMsg.ROBOT_KIT_LEFT.text(kit.name(),
                    left.entrySet().stream().filter(e -> kit.owned(e.getKey()) > 0)
                            .map(e -> e.getKey().count(e.getValue()).toString()).collect(Collectors.joining(", "))));
        }
        if (!d.problems().isEmpty()) {
            s.append(s.length() == 0 ? "" : "   ").append(ToolMsg.ROBOT_PROBLEMS.text(d.problems().size(), d.problems().get(0).format()));
        }
        return s.toString();
    }

    private static String ids(List<Integer> ids) {
        return ids.stream().map(String::valueOf).collect(Collectors.joining(", "));
    }
}
