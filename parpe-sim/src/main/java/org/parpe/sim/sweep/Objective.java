package org.parpe.sim.sweep;

import java.util.Locale;
import org.parpe.sim.text.SimMsg;

/** What a sweep's plot shows and an optimisation maximises; every one is larger for a better gait. */
public enum Objective {
    /** How fast the robot went forwards (+x), m/s: the ranking of {@code parpe race} per second. */
    FORWARD_SPEED("forward-speed", SimMsg.OBJECTIVE_FORWARD_SPEED),
    /** How fast it went in any direction, m/s. */
    SPEED("speed", SimMsg.OBJECTIVE_SPEED),
    /** How far it went forwards (+x), m. */
    FORWARD("forward", SimMsg.OBJECTIVE_FORWARD),
    /** How far it went in any direction, m. */
    DISTANCE("distance", SimMsg.OBJECTIVE_DISTANCE),
    /** The score of the run in its world (sweeps with a world only). */
    SCORE("score", SimMsg.OBJECTIVE_SCORE);

    private final String id;
    private final SimMsg label;

    Objective(String id, SimMsg label) {
        this.id = id;
        this.label = label;
    }

    /** The name used on the command line ({@code forward-speed}). */
    public String id() {
        return id;
    }

    /** A label for an axis, with the unit, in the chosen language. */
    public String label() {
        return label.text();
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
