package org.parpe.serial.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** The decoders' one receive buffer (issue 32 item 6: G1's and the control-table protocols' decoders each kept their own). */
class ReceiveBufferTest {
    @Test
    void takesWhatFitsAndMovesPendingBytesToTheFrontWhenFull() {
        ReceiveBuffer rx = new ReceiveBuffer(4);
        assertEquals(3, rx.append(new byte[] {1, 2, 3}, 0, 3));
        assertEquals(1, rx.append(new byte[] {9, 4, 5}, 1, 2)); // room for one only
        rx.consumeTo(2);
        assertEquals(2, rx.pending());
        assertEquals(1, rx.append(new byte[] {5}, 0, 1)); // full: 3, 4 move to the front first
        assertEquals(0, rx.start());
        assertEquals(3, rx.end());
        assertArrayEquals(new byte[] {3, 4, 5}, Arrays.copyOfRange(rx.bytes(), rx.start(), rx.end()));
    }

    @Test
    void settlingWithNothingPendingStartsAtTheFrontAgain() {
        ReceiveBuffer rx = new ReceiveBuffer(8);
        rx.append(new byte[] {1, 2, 3}, 0, 3);
        rx.settle(2);
        assertEquals(2, rx.start());
        rx.settle(3);
        assertEquals(0, rx.start());
        assertEquals(0, rx.end());
    }
}
