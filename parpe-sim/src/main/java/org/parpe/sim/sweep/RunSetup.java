package org.parpe.sim.sweep;

import java.nio.file.Path;
import java.util.Map;
import org.parpe.core.load.ParsedScript;

/**
 * What every run of a sweep shares, with the script already read (once per sweep): what a
 * {@link Lanes lane} needs to make the same runs as the application's own {@link Evaluator}.
 *
 * @param script      the script with its includes and robot file, as read when the sweep started
 * @param text        the main file's text (an editor's buffer may differ from the file)
 * @param fixed       parameter values that stay the same in every run ({@code --param})
 * @param robot       the simulated robot: {@code GENERATOR[:key=value,...]}, a configuration file,
 *                    or {@link org.parpe.sim.SimTarget#AUTO} to pick it from the script
 * @param duration    simulated seconds per run
 * @param tick        the scheduler's tick, s
 * @param fallTiltDeg the tilt beyond which the robot counts as fallen over, degrees
 * @param world       the world file every run is in and scored by, or null for the flat floor
 */
public record RunSetup(ParsedScript script, String text, Map<String, Double> fixed, String robot, double duration,
                       double tick, double fallTiltDeg, Path world) {
    public RunSetup {
        fixed = Map.copyOf(fixed);
    }
}
