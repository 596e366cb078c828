package org.parpe.sim.sweep;

/**
 * Conditions a good gait must meet besides its objective.
 *
 * @param maxTiltDeg the largest tilt allowed, degrees ({@code +∞}: any)
 * @param notFallen  whether a run whose robot fell over is rejected
 */
public record Constraints(double maxTiltDeg, boolean notFallen) {

    /** No constraint. */
    public static final Constraints NONE = new Constraints(Double.POSITIVE_INFINITY, false);

    public Constraints {
        if (!(maxTiltDeg >= 0)) {
            throw new IllegalArgumentException("the tilt limit must be >= 0 degrees, got " + maxTiltDeg);
        }
    }

    /**
     * How far {@code row} is from meeting the constraints: 0 when it meets them, more the
     * further it is (a failed run is furthest).
     */
    public double violation(SweepRow row) {
        if (!row.ok() || Double.isNaN(row.maxTiltDeg())) {
            return 1000;
        }
        double v = Math.max(0, row.maxTiltDeg() - maxTiltDeg);
        return v + (notFallen && row.fell() ? 180 : 0);
    }
}
