package org.parpe.gui.grid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/** Issue 23, item 10: Wave… refused lesson 2's own "−1/6". */
class WaveNumberTest {
    @Test
    void fractionsMinusSignsAndDecimalCommasAreNumbers() {
        assertEquals(-1.0 / 6, WaveDialog.number("-1/6"));
        assertEquals(-1.0 / 6, WaveDialog.number("\u22121/6"));
        assertEquals(0.25, WaveDialog.number("0,25"));
        assertEquals(30.0, WaveDialog.number(" 30 "));
        assertNull(WaveDialog.number("1/0"));
        assertNull(WaveDialog.number("six"));
    }
}
