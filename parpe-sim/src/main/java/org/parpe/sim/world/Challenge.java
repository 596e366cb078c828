package org.parpe.sim.world;

import java.nio.file.Path;
import java.util.Map;
import java.util.Set;

/**
 * A class challenge (format in {@code docs/simulator.md}, "Challenges"): the world every student's
 * robot runs in, the robot, the run's length and tick, the parameter values every script gets,
 * the rules a script must keep and how equal scores are told apart. Read by
 * {@link ChallengeReader}; {@code parpe grade} runs a folder of scripts in it.
 *
 * @param file        the challenge file
 * @param world       the world file, relative names resolved against the challenge's folder
 * @param robot       the robot for every script: {@code GENERATOR[:key=value,...]} or a configuration file
 * @param duration    simulated seconds per run
 * @param tick        the scheduler tick, s
 * @param parameters  values given to the scripts' parameters of these names (the others keep their defaults)
 * @param maxModules  the most modules a script's robot may declare
 * @param sensors     the sensor types a script may declare and read ({@code angle}, {@code accel},
 *                    {@code touch}, {@code dock}); all of them unless the challenge names some
 * @param tieBreak    how runs with equal scores are ordered
 */
public record Challenge(Path file, Path world, String robot, double duration, double tick,
                        Map<String, Double> parameters, int maxModules, Set<String> sensors, TieBreak tieBreak) {
    /** How runs with equal scores are ordered; runs still equal share a rank (1, 1, 3). */
    public enum TieBreak {
        /** The one that went further forwards (+x) ranks first. */
        DISTANCE,
        /** Equal scores share a rank. */
        NONE
    }

    public Challenge {
        parameters = Map.copyOf(parameters);
        sensors = Set.copyOf(sensors);
    }
}
