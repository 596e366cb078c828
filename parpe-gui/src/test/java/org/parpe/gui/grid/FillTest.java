package org.parpe.gui.grid;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.gui.grid.Fill.Selection;
import org.parpe.gui.grid.TableEdits.At;

/** The travelling wave and spreadsheet paste written into a selection. */
class FillTest {

    @Test
    void travellingWaveFollowsTheDocumentedFormula() {
        Map<At, String> w = Fill.wave(new Selection(2, 3, 5, 4), 10, 0.25);
        assertEquals(8, w.size());
        assertEquals("0", w.get(new At(2, 3)), "r = 0, c = 0: sin 0");
        assertEquals("10", w.get(new At(2, 4)), "c = 1: sin(2pi/4)");
        assertEquals("10", w.get(new At(3, 3)), "r = 1 of 4 rows: sin(2pi/4)");
        assertEquals("0", w.get(new At(4, 3)), "sin(pi) rounds to 0, never -0");
        assertEquals("-10", w.get(new At(5, 3)));
        assertEquals("-7.1", Fill.wave(new Selection(0, 0, 7, 0), 10, 0).get(new At(5, 0)), "10 sin(5pi/4) = -7.07");
    }

    @Test
    void numbersAreRoundedToATenth() {
        assertEquals("15", Fill.number(15.0));
        assertEquals("12.5", Fill.number(12.45));
        assertEquals("-3", Fill.number(-3.04));
        assertEquals("0", Fill.number(-0.04));
    }

    @Test
    void pasteTakesTabsOrCommasAndLeavesOutWhatFallsOutside() {
        int[] outside = {0};
        Map<At, String> p = Fill.paste("1\t2\t3\r\n4\t\t6\n", new Selection(1, 1, 1, 1), 3, 3, outside);
        assertEquals(Map.of(new At(1, 1), "1", new At(1, 2), "2", new At(2, 1), "4"), p);
        assertEquals(2, outside[0], "3 and 6 fall past the last column; the empty cell is skipped, not counted");
        assertEquals(List.of(List.of("a", "max(1, 2)", "c")), Fill.parse("a, max(1, 2), c"));
        Map<At, String> one = Fill.paste("9", new Selection(0, 0, 1, 1), 5, 5, outside);
        assertEquals(4, one.size(), "one cell fills the whole selection");
    }
}
