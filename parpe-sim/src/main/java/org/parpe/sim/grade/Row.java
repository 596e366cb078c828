package org.parpe.sim.grade;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.parpe.sim.world.Challenge;

/**
 * One line of the report: a student, the outcome of its run, its trace (relative to the report's
 * folder, "" without one), its centre-of-mass path (x, y pairs) and its rank (0: not ranked).
 */
public record Row(Students.Student student, Outcome outcome, String trace, double[] path, int rank) {

    /**
     * {@code rows} in report order with their ranks: ranked runs by score, then (with
     * {@link Challenge.TieBreak#DISTANCE}) by how far they went forwards; runs still equal share a
     * rank and the next rank skips (competition ranking, 1, 1, 3, as {@code parpe race}); then the
     * runs that failed, each in name order.
     */
    public static List<Row> ranked(List<Row> rows, Challenge.TieBreak tie) {
        Comparator<Row> key = Comparator.comparingDouble((Row r) -> -r.outcome().score());
        if (tie == Challenge.TieBreak.DISTANCE) {
            key = key.thenComparingDouble(r -> -r.outcome().dx());
        }
        Comparator<Row> rankedFirst = Comparator.comparing((Row r) -> !r.outcome().ranked());
        final Comparator<Row> byKey = key;
        List<Row> sorted = new ArrayList<>(rows);
        sorted.sort(rankedFirst.thenComparing((a, b) -> a.outcome().ranked() ? byKey.compare(a, b) : 0)
                .thenComparing(r -> r.student().name()));
        List<Row> out = new ArrayList<>();
        for (int i = 0; i < sorted.size(); i++) {
            Row r = sorted.get(i);
            int rank = 0;
            if (r.outcome().ranked()) {
                rank = i > 0 && out.get(i - 1).rank() > 0 && byKey.compare(sorted.get(i - 1), r) == 0 ? out.get(i - 1).rank() : i + 1;
            }
            out.add(new Row(r.student(), r.outcome(), r.trace(), r.path(), rank));
        }
        return out;
    }
}
