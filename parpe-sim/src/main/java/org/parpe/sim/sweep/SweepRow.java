package org.parpe.sim.sweep;

import java.util.Map;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.text.Message;
import org.parpe.sim.text.SimMsg;
import org.parpe.sim.world.WorldScore;

/**
 * The result of one simulated run: its {@link Point} and what the robot did.
 *
 * @param point          which run it was
 * @param duration       simulated seconds covered
 * @param distance       horizontal displacement of the centre of mass, m
 * @param forward        its component forwards (+x, the way every standard robot faces), m
 * @param forwardSpeed   {@code forward / duration}, m/s
 * @param speed          {@code distance / duration}, m/s
 * @param maxTiltDeg     the largest tilt of the root part from the vertical, degrees
 * @param jointTravelDeg the energy proxy: the summed rotation of every measured joint, degrees
 *                       (a servo's work grows with how far it turns)
 * @param fell           whether the robot fell over (its tilt passed the sweep's limit)
 * @param error          the run-time error (or the reason the run could not start), shown in the
 *                       user's language where it is shown ({@link Message#EMPTY} if none); the
 *                       numbers are NaN when the run could not start
 * @param score          the world's score of the run, NaN without a world
 * @param parts          the score's parts, null without a world or where only the score is
 *                       known (a row read back from a CSV file)
 */
public record SweepRow(Point point, double duration, double distance, double forward, double forwardSpeed,
                       double speed, double maxTiltDeg, double jointTravelDeg, boolean fell, Message error,
                       double score, WorldScore parts) {

    /** A row whose score is known without its parts. */
    public SweepRow(Point point, double duration, double distance, double forward, double forwardSpeed,
                    double speed, double maxTiltDeg, double jointTravelDeg, boolean fell, Message error, double score) {
        this(point, duration, distance, forward, forwardSpeed, speed, maxTiltDeg, jointTravelDeg, fell, error, score,
                null);
    }

    /** A row of a run on the flat floor (no score). */
    public SweepRow(Point point, double duration, double distance, double forward, double forwardSpeed,
                    double speed, double maxTiltDeg, double jointTravelDeg, boolean fell, Message error) {
        this(point, duration, distance, forward, forwardSpeed, speed, maxTiltDeg, jointTravelDeg, fell, error,
                Double.NaN);
    }

    /** The varied parameters' values. */
    public Map<String, Double> values() {
        return point.values();
    }

    /** Whether the run went to its end without an error. */
    public boolean ok() {
        return Message.EMPTY.equals(error);
    }

    /** {@code d} as a row's error: {@code FILE:LINE:COL: error: MESSAGE}, the message in the user's language. */
    public static Message error(Diagnostic d) {
        return Message.of(SimMsg.LOAD_ERROR, d.pos(), d.severity().word(), d.text());
    }
}
