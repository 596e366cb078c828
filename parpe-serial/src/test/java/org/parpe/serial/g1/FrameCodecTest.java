package org.parpe.serial.g1;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.parpe.serial.bus.Crc16;

class FrameCodecTest {

    record Got(int addr, int cmd, byte[] payload) {
    }

    private final List<Got> got = new ArrayList<>();
    private final FrameDecoder decoder = new FrameDecoder(
            (a, c, b, o, l) -> got.add(new Got(a, c, Arrays.copyOfRange(b, o, o + l))));

    @Test
    void crcMatchesTheCcittFalseCheckValue() {
        byte[] check = "123456789".getBytes(StandardCharsets.US_ASCII);
        assertEquals(0x29B1, Crc16.CCITT_FALSE.of(check, 0, check.length));
    }

    @Test
    void aPingFrameHasTheDocumentedBytes() {
        FrameEncoder e = new FrameEncoder();
        int n = e.simple(3, Command.PING);
        byte[] head = Arrays.copyOf(e.buffer(), 6);
        assertArrayEquals(new byte[] {(byte) 0xA5, 0x5A, 3, 0, 0, 1}, head);
        assertEquals(8, n);
        assertEquals(Crc16.CCITT_FALSE.of(e.buffer(), 2, 4), (e.buffer()[6] & 0xFF) << 8 | (e.buffer()[7] & 0xFF));
    }

    @Test
    void setpointsRoundTrip() {
        FrameEncoder e = new FrameEncoder();
        short[] wire = {Protocol.toWire(12.34), Protocol.NO_CHANGE, Protocol.toWire(-90)};
        int n = e.setpoints(513, 4, wire, 3);
        assertEquals(Protocol.setpointFrameLength(3), n);
        decoder.feed(e.buffer(), 0, n);
        assertEquals(1, got.size());
        Got g = got.get(0);
        assertEquals(Protocol.BROADCAST, g.addr());
        assertEquals(Command.SETPOINTS.code(), g.cmd());
        assertEquals(513, FrameHandler.u16(g.payload(), 0));
        assertEquals(4, g.payload()[2]);
        assertEquals(1234, FrameHandler.i16(g.payload(), 3));
        assertEquals(Protocol.NO_CHANGE, FrameHandler.i16(g.payload(), 5));
        assertEquals(-9000, FrameHandler.i16(g.payload(), 7));
    }

    @Test
    void framesSplitAtEveryByteStillDecode() {
        FrameEncoder e = new FrameEncoder();
        int n = e.begin(7, Command.STATUS).putU16(-4500).putU8(10).putU8(-100).putU8(0).putU8(3).putU8(1)
                .putU16(9).finish();
        for (int i = 0; i < n; i++) {
            decoder.feed(e.buffer(), i, 1);
        }
        assertEquals(1, got.size());
        assertEquals(-4500, FrameHandler.i16(got.get(0).payload(), 0));
    }

    @Test
    void everySingleByteCorruptionIsRejectedAndTheNextFrameSurvives() {
        FrameEncoder e = new FrameEncoder();
        short[] wire = new short[55];
        Arrays.fill(wire, (short) 1500);
        int n = e.setpoints(1, 0, wire, 55);
        byte[] good = Arrays.copyOf(e.buffer(), n);
        for (int i = 2; i < n; i++) {
            for (int flip = 1; flip < 256; flip += 37) {
                byte[] bad = good.clone();
                bad[i] ^= (byte) flip;
                got.clear();
                decoder.feed(bad, 0, n);
                decoder.feed(good, 0, n);
                decoder.idle();
                assertEquals(1, got.size(), "byte " + i + " xor " + flip);
            }
        }
        assertEquals(0, decoder.pending());
    }

    @Test
    void garbageBetweenFramesIsSkippedAndCounted() {
        FrameEncoder e = new FrameEncoder();
        int n = e.simple(1, Command.PING);
        byte[] frame = Arrays.copyOf(e.buffer(), n);
        decoder.feed(new byte[] {1, 2, (byte) 0xA5, 9}, 0, 4);
        decoder.feed(frame, 0, n);
        assertEquals(1, got.size());
        assertEquals(4, decoder.garbageBytes());
    }

    @Test
    void aLengthBeyondTheBoundIsResynchronised() {
        byte[] bogus = {(byte) 0xA5, 0x5A, 1, (byte) 0xFF, (byte) 0xFF, 1};
        decoder.feed(bogus, 0, bogus.length);
        FrameEncoder e = new FrameEncoder();
        int n = e.simple(2, Command.READ);
        decoder.feed(e.buffer(), 0, n);
        assertEquals(1, got.size());
        assertEquals(2, got.get(0).addr());
    }

    @Test
    void anOverlongPayloadIsRefused() {
        FrameEncoder e = new FrameEncoder();
        assertThrows(IllegalArgumentException.class, () -> e.setpoints(0, 0, new short[400], 400));
    }

    @Test
    void wireAnglesRoundToHundredths() {
        assertEquals(4512, Protocol.toWire(45.115));
        assertEquals(-4512, Protocol.toWire(-45.115));
        assertEquals(45.12, Protocol.fromWire(4512), 1e-12);
        assertEquals(true, Protocol.wireInRange(9000));
        assertEquals(false, Protocol.wireInRange(9001));
    }
}
