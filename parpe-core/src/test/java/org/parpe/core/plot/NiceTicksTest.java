package org.parpe.core.plot;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The one tick algorithm of the IDE's charts (issue 19 item 6: there were three). */
class NiceTicksTest {

    @Test
    void stepsAreOneTwoOrFiveTimesAPowerOfTen() {
        assertEquals(2, NiceTicks.step(10, 5), 1e-12);
        assertEquals(0.5, NiceTicks.step(2.2, 5), 1e-12);
        assertEquals(50, NiceTicks.step(330, 6), 1e-12);
        assertEquals(1, NiceTicks.step(6, 6), 1e-12);
    }

    @Test
    void ticksAreTheMultiplesOfTheStepWithinTheRange() {
        assertArrayEquals(new double[] {-50, 0, 50}, NiceTicks.within(-90, 90, 4), 1e-9);
        assertArrayEquals(new double[] {0.2, 0.4, 0.6}, NiceTicks.within(0.13, 0.7, 3), 1e-9);
        assertArrayEquals(new double[] {12, 14, 16, 18, 20}, NiceTicks.within(11.5, 20, 5), 1e-9);
    }

    @Test
    void anEmptyOrBrokenRangeHasNoTicks() {
        assertEquals(0, NiceTicks.within(3, 3, 5).length);
        assertEquals(0, NiceTicks.within(Double.NaN, 1, 5).length);
        assertEquals(0, NiceTicks.within(0, Double.POSITIVE_INFINITY, 5).length);
    }

    @Test
    void labelsHaveTheDecimalsOfTheStep() {
        assertEquals("0.25", NiceTicks.label(0.25, 0.05));
        assertEquals("10", NiceTicks.label(10, 5));
        assertEquals("0.0", NiceTicks.label(-1e-17, 0.1), "no minus zero");
    }

    @Test
    void commandedIsDashedAndMeasuredSolid() {
        assertTrue(PlotStyle.dashed(true));
        assertFalse(PlotStyle.dashed(false));
        assertEquals(PlotStyle.series(0), PlotStyle.series(8), "the colours repeat after eight modules");
    }
}
