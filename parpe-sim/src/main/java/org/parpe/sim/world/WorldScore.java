package org.parpe.sim.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.parpe.core.text.Message;
import org.parpe.sim.text.SimMsg;

/**
 * The score of a run in a world and its parts.
 *
 * @param score        the sum of the parts' points, or 0 if the robot was disqualified
 * @param timeToZone   simulated seconds until the robot's centre of mass first entered the goal
 *                     zone, NaN if it never did (or the world has no goal)
 * @param pathDistance metres of progress along start → checkpoints, the best reached
 * @param checkpoints  checkpoints passed, in order
 * @param delivered    objects lying in their delivery zones at the end
 * @param presses      lever presses
 * @param disqualified why the robot was disqualified ("tilt", "arena"), or empty
 */
public record WorldScore(double score, double timeToZone, double pathDistance, int checkpoints, int delivered,
                         int presses, String disqualified) {

    /**
     * The parts that count, in words, as {@code parpe race} and {@code parpe optimize} print them:
     * "zone 31.2 s, path 1.40 m, 2 checkpoints, 1 delivered, 2 presses, disqualified (tilt)", or
     * "-" when none does; in the chosen language ({@link org.parpe.core.text.Lang}).
     */
    public String inWords() {
        List<Message> p = new ArrayList<>();
        if (!Double.isNaN(timeToZone)) {
            p.add(Message.of(SimMsg.SCORE_ZONE, String.format(Locale.ROOT, "%.1f", timeToZone)));
        }
        if (pathDistance > 0) {
            p.add(Message.of(SimMsg.SCORE_PATH, String.format(Locale.ROOT, "%.2f", pathDistance)));
        }
        if (checkpoints > 0) {
            p.add(Message.of(checkpoints == 1 ? SimMsg.SCORE_CHECKPOINT : SimMsg.SCORE_CHECKPOINTS, checkpoints));
        }
        if (delivered > 0) {
            p.add(Message.of(SimMsg.SCORE_DELIVERED, delivered));
        }
        if (presses > 0) {
            p.add(Message.of(presses == 1 ? SimMsg.SCORE_PRESS : SimMsg.SCORE_PRESSES, presses));
        }
        if (!disqualified.isEmpty()) {
            p.add(Message.of(SimMsg.SCORE_DISQUALIFIED, switch (disqualified) {
                case "tilt" -> Message.of(SimMsg.SCORE_TILT);
                case "arena" -> Message.of(SimMsg.SCORE_ARENA);
                default -> disqualified;
            }));
        }
        return p.isEmpty() ? "-" : String.join(SimMsg.LIST_SEPARATOR.text(), p.stream().map(Message::toString).toList());
    }

    /** The score's fields as JSON members (without braces), to add to the simulator's metrics. */
    public String jsonMembers() {
        return String.format(Locale.ROOT, "\"score\": %.6f, \"timeToZone\": %s, \"pathDistance\": %.6f, "
                        + "\"checkpoints\": %d, \"delivered\": %d, \"presses\": %d, \"disqualified\": \"%s\"",
                score, Double.isNaN(timeToZone) ? "null" : String.format(Locale.ROOT, "%.6f", timeToZone),
                pathDistance, checkpoints, delivered, presses, disqualified);
    }
}
