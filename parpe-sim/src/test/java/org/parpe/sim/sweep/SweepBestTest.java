package org.parpe.sim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.Message;

/**
 * The rule of "best" that {@code parpe sweep} and the IDE share (issue 23, item 1: lesson 11's
 * sweep crowned run 18, a snake tilted 97.6° that fell over). Failed before the rule excluded
 * fallen runs.
 */
class SweepBestTest {

    private static SweepRow row(int index, double forwardSpeed, double tilt, boolean fell, String error) {
        Point p = new Point(index, index, 0, Map.of("bend", 10.0 * index), 0);
        return new SweepRow(p, 30, forwardSpeed * 30, forwardSpeed * 30, forwardSpeed, forwardSpeed, tilt, 1000, fell,
                error.isEmpty() ? Message.EMPTY : Message.verbatim(error));
    }

    // Lesson 11's runs 12 (bend 50, upright), 15 and 18 (faster, but fallen over), from its CSV.
    private final List<SweepRow> lesson11 = List.of(row(12, 0.224728, 86.2, false, ""), row(15, 0.256678, 94.2, true, ""),
            row(18, 0.265427, 97.6, true, ""));

    @Test
    void aFallenRunIsNeverTheBestByDefault() {
        assertEquals(12, new SweepResult(lesson11, false).best(Objective.FORWARD_SPEED).orElseThrow().point().index());
    }

    @Test
    void fallenRunsCountOnlyWhenTheRuleSaysSo() {
        assertEquals(18, SweepResult.best(lesson11, Objective.FORWARD_SPEED, r -> true).orElseThrow().point().index());
    }

    @Test
    void whenEveryRunFellOrFailedThereIsNoBest() {
        List<SweepRow> none = List.of(row(0, 0.3, 120, true, ""), row(1, Double.NaN, Double.NaN, false, "no robot"));
        assertTrue(new SweepResult(none, false).best(Objective.FORWARD_SPEED).isEmpty());
    }

    @Test
    void theFirstAmongEqualsWins() {
        List<SweepRow> tie = List.of(row(3, 0.1, 5, false, ""), row(4, 0.1, 5, false, ""));
        assertEquals(3, new SweepResult(tie, false).best(Objective.FORWARD_SPEED).orElseThrow().point().index());
    }
}
