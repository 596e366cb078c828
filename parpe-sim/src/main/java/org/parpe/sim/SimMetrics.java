package org.parpe.sim;

import java.util.Locale;

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
 */
public record SimMetrics(double duration, double distance, double dx, double dy, double speed,
                         double maxTiltDeg) {

    /** The tilt beyond which a robot counts as fallen over unless told otherwise, degrees (a sweep's {@code --fall-tilt}). */
    public static final double FALL_TILT_DEG = 90;

    /** Whether the robot tilted past {@link #FALL_TILT_DEG}: it fell over. */
    public boolean fell() {
        return maxTiltDeg > FALL_TILT_DEG;
    }

    /** The metrics as one JSON object, numbers with 6 decimals. */
    public String toJson() {
        return String.format(Locale.ROOT,
                "{\"duration\": %.6f, \"distance\": %.6f, \"dx\": %.6f, \"dy\": %.6f, \"speed\": %.6f, "
                        + "\"maxTiltDeg\": %.6f}",
                duration, distance, dx, dy, speed, maxTiltDeg);
    }
}
