package org.parpe.sim;

import java.util.Locale;
import org.parpe.sim.world.WorldScore;

/**
 * How far and how steadily the robot went during a run.
 *
 * @param duration   simulated seconds covered
 * @param distance   horizontal displacement of the centre of mass, m
 * @param dx         its x component, m
 * @param dy         its y component, m
 * @param speed      {@code distance / duration}, m/s
 * @param maxTiltDeg the largest angle, degrees, between the root part's initially vertical
 *                   axis and the vertical (how far the robot pitched, rolled or fell over)
 * @param score      the score and its parts in a world, or null on the flat floor
 */
public record SimMetrics(double duration, double distance, double dx, double dy, double speed,
                         double maxTiltDeg, WorldScore score) {

    /** Metrics on the flat floor (no score). */
    public SimMetrics(double duration, double distance, double dx, double dy, double speed, double maxTiltDeg) {
        this(duration, distance, dx, dy, speed, maxTiltDeg, null);
    }

    /** These metrics with {@code worldScore}. */
    public SimMetrics withScore(WorldScore worldScore) {
        return new SimMetrics(duration, distance, dx, dy, speed, maxTiltDeg, worldScore);
    }

    /** The tilt beyond which a robot counts as fallen over unless told otherwise, degrees (a sweep's {@code --fall-tilt}). */
    public static final double FALL_TILT_DEG = 90;

    /** Whether the robot tilted past {@link #FALL_TILT_DEG}: it fell over. */
    public boolean fell() {
        return maxTiltDeg > FALL_TILT_DEG;
    }

    /** The metrics as one JSON object, numbers with 6 decimals; in a world with the score and its parts. */
    public String toJson() {
        return String.format(Locale.ROOT,
                "{\"duration\": %.6f, \"distance\": %.6f, \"dx\": %.6f, \"dy\": %.6f, \"speed\": %.6f, "
                        + "\"maxTiltDeg\": %.6f%s}",
                duration, distance, dx, dy, speed, maxTiltDeg, score == null ? "" : ", " + score.jsonMembers());
    }
}
