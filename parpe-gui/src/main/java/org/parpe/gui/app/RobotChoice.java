package org.parpe.gui.app;

import java.nio.file.Path;
import java.util.Locale;
import org.parpe.core.model.Group;
import org.parpe.core.model.Program;

/**
 * The simulated robot for a script: a generator name or a configuration file chosen in the
 * 3D view's picker, or {@value #AUTO}, which guesses from the script (its file name and group
 * names) which of the simulator's standard robots fits.
 */
final class RobotChoice {
    static final String AUTO = "auto";

    private RobotChoice() {
    }

    /** The specification to give {@code RobotConfigs.resolve} for {@code choice}. */
    static String spec(String choice, Program program) {
        if (!AUTO.equals(choice)) {
            return choice;
        }
        String file = Path.of(program.file()).getFileName().toString().toLowerCase(Locale.ROOT);
        for (String g : new String[] {"centipede", "wheel", "loop", "humanoid", "snake"}) {
            if (file.contains(g)) {
                return g;
            }
        }
        boolean left = false;
        boolean right = false;
        for (Group g : program.robot().groups()) {
            String n = g.name().toLowerCase(Locale.ROOT);
            if (n.contains("wheel")) {
                return "wheel";
            }
            if (n.contains("loop") || n.contains("ring")) {
                return "loop";
            }
            left |= n.startsWith("left");
            right |= n.startsWith("right");
            if (n.contains("leg") || n.contains("arm")) {
                left = right = true;
            }
        }
        return left && right ? "centipede" : "snake";
    }
}
