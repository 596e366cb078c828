package org.parpe.sim.sweep;

import java.util.Locale;

/** What a sweep's plot shows and an optimisation maximises; every one is larger for a better gait. */
public enum Objective {
    /** How fast the robot went forwards (+x), m/s: the ranking of {@code parpe race} per second. */
    FORWARD_SPEED("forward-speed", "forward speed (m/s)"),
    /** How fast it went in any direction, m/s. */
    SPEED("speed", "speed (m/s)"),
    /** How far it went forwards (+x), m. */
    FORWARD("forward", "forward (m)"),
    /** How far it went in any direction, m. */
    DISTANCE("distance", "distance (m)"),
    /** The score of the run in its world (sweeps with a world only). */
    SCORE("score", "score (points)");

    private final String id;
    private final String label;

    Objective(String id, String label) {
        this.id = id;
        this.label = label;
    }

    /** The name used on the command line ({@code forward-speed}). */
    public String id() {
        return id;
    }

    /** A label for an axis, with the unit. */
    public String label() {
        return label;
    }

    /** The objective of {@code row} (NaN when the run could not start). */
    public double of(SweepRow row) {
        return switch (this) {
            case FORWARD_SPEED -> row.forwardSpeed();
            case SPEED -> row.speed();
            case FORWARD -> row.forward();
            case DISTANCE -> row.distance();
            case SCORE -> row.score();
        };
    }

    /** The objective named {@code id}, or {@code null}. */
    public static Objective byId(String id) {
        for (Objective o : values()) {
            if (o.id.equals(id.trim().toLowerCase(Locale.ROOT))) {
                return o;
            }
        }
        return null;
    }

    /** The command-line names of every objective, comma separated. */
    public static String ids() {
        return String.join(", ", java.util.Arrays.stream(values()).map(Objective::id).toList());
    }
}
