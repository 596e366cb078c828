package org.parpe.sim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.Message;

/**
 * Issue 18 items 8 and 10: an error cell that begins with {@code =} (a script named
 * {@code =HYPERLINK(...).xml}) was written as a formula; a grid of 999 999 999 values or a
 * random draw over 0..10^12 integers filled the memory before being refused. Both failed before.
 */
class SweepCsvCellTest {
    @Test
    void anErrorCellThatASpreadsheetWouldEvaluateGetsAnApostrophe() {
        Point p = new Point(0, 0, 0, Map.of("amp", -1.5), 1);
        SweepRow row = new SweepRow(p, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN,
                false, Message.verbatim("=HYPERLINK(\"http://x\").xml:1:1: error: bad"));
        String line = SweepCsv.line(row, 1);
        assertTrue(line.endsWith(",\"'=HYPERLINK(\"\"http://x\"\").xml:1:1: error: bad\""), line);
        assertTrue(line.contains(",-1.5,"), "a negative number stays a number: " + line);
    }

    @Test
    void hugeSweepsAreRefusedAtOnceWithTheirCount() {
        Axis amp = Axis.even("amp", 0, 40, 999_999_999);
        SweepException e = assertThrows(SweepException.class, () -> SweepSpec.grid(List.of(amp), 1, 1).check());
        assertTrue(e.getMessage().startsWith("the sweep has 999999999 runs, more than the 10000000"), e.getMessage());
        Axis huge = Axis.integers("n", 0, 1_000_000_000_000L);
        assertEquals(1_000_000_000_001L, huge.count());
        SweepSpec random = SweepSpec.random(List.of(huge), 3, 1, 7);
        double v = random.point(2).values().get("n");
        assertTrue(v >= 0 && v <= 1e12 && v == Math.rint(v), "drawn " + v);
        SweepException grid = assertThrows(SweepException.class, () -> SweepSpec.grid(List.of(huge, amp), 2, 1).check());
        assertTrue(grid.getMessage().startsWith("the sweep has more than 9.2e18 runs"), grid.getMessage());
    }
}
