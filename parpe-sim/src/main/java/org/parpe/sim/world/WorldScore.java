package org.parpe.sim.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

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

    /** The score's fields as JSON members (without braces), to add to the simulator's metrics. */
    public String jsonMembers() {
        return String.format(Locale.ROOT, "\"score\": %.6f, \"timeToZone\": %s, \"pathDistance\": %.6f, "
                        + "\"checkpoints\": %d, \"delivered\": %d, \"presses\": %d, \"disqualified\": \"%s\"",
                score, Double.isNaN(timeToZone) ? "null" : String.format(Locale.ROOT, "%.6f", timeToZone),
                pathDistance, checkpoints, delivered, presses, disqualified);
    }

    /**
     * The parts of the score that count, in words: "zone 31.2 s, path 1.40 m, 1 delivered, 2 presses,
     * disqualified (tilt)", or "-" when none does (what {@code parpe race} and the IDE show).
     */
    public String parts() {
        List<String> p = new ArrayList<>();
        if (!Double.isNaN(timeToZone)) {
            p.add(String.format(Locale.ROOT, "zone %.1f s", timeToZone));
        }
        if (pathDistance > 0) {
            p.add(String.format(Locale.ROOT, "path %.2f m", pathDistance));
        }
        if (delivered > 0) {
            p.add(delivered + " delivered");
        }
        if (presses > 0) {
            p.add(presses + (presses == 1 ? " press" : " presses"));
        }
        if (!disqualified.isEmpty()) {
            p.add("disqualified (" + disqualified + ")");
        }
        return p.isEmpty() ? "-" : String.join(", ", p);
    }
}
