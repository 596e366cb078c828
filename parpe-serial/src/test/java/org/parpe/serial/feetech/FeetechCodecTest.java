package org.parpe.serial.feetech;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.parpe.serial.dynamixel.Dxl2CodecTest.hex;
import static org.parpe.serial.dynamixel.Dxl2CodecTest.hexOf;
import static org.parpe.serial.dynamixel.Dxl2CodecTest.params;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.parpe.serial.servo.wire.PacketCodec;
import org.parpe.serial.servo.wire.PacketDecoder;

/**
 * Feetech STS/SCS packets byte for byte against the examples of Feetech's communication protocol
 * manual (ping, read, write), and the checksum rule ~(ID + LEN + INST + params).
 */
class FeetechCodecTest {
    final FeetechCodec codec = new FeetechCodec();
    final byte[] out = new byte[codec.bufferSize()];

    byte[] instruction(int id, int inst, int... p) {
        return Arrays.copyOf(out, codec.instruction(out, id, inst, params(p), p.length));
    }

    List<String> decode(byte[] bytes) {
        List<String> got = new ArrayList<>();
        PacketDecoder d = codec.decoder(p -> got.add(p.id + ":" + p.code + ":" + hexOf(Arrays.copyOf(p.params, p.length))));
        d.feed(bytes, 0, bytes.length);
        return got;
    }

    @Test
    void pingAndItsReplyAsInTheManual() {
        assertArrayEquals(hex("FF FF 01 02 01 FB"), instruction(1, PacketCodec.PING));
        byte[] reply = hex("FF FF 01 02 00 FC");
        assertArrayEquals(reply, Arrays.copyOf(out, codec.status(out, 1, 0, new byte[0], 0)));
        assertEquals(List.of("1:0:"), decode(reply));
    }

    @Test
    void readPresentPositionAsInTheManual() {
        // Address 0x38 (56), two bytes.
        assertArrayEquals(hex("FF FF 01 04 02 38 02 BE"), instruction(1, PacketCodec.READ, 0x38, 0x02));
    }

    @Test
    void writeGoalPositionTimeAndSpeedAsInTheManual() {
        // Goal 2048 (0x0800), time 0, speed 1000 (0x03E8), little-endian (STS).
        assertArrayEquals(hex("FF FF 01 09 03 2A 00 08 00 00 E8 03 D5"), instruction(1, PacketCodec.WRITE,
                0x2A, 0x00, 0x08, 0x00, 0x00, 0xE8, 0x03));
    }

    @Test
    void syncWriteLayoutAndChecksum() {
        byte[] p = instruction(0xFE, PacketCodec.SYNC_WRITE, 0x2A, 2, 1, 0x00, 0x08, 2, 0xFF, 0x07);
        assertArrayEquals(hex("FF FF FE 0A 83 2A 02 01 00 08 02 FF 07"), Arrays.copyOf(p, p.length - 1));
        assertEquals(FeetechCodec.checksum(p, 2, p.length - 3), p[p.length - 1] & 0xFF);
    }

    @Test
    void statusWithErrorBitsAndGarbageAround() {
        byte[] st = Arrays.copyOf(out, codec.status(out, 7, FeetechCodec.ERROR_OVERLOAD | FeetechCodec.ERROR_OVERHEAT,
                params(0x34, 0x12), 2));
        byte[] stream = new byte[st.length + 5];
        stream[0] = (byte) 0xFF;
        stream[1] = 0x13;
        stream[2] = (byte) 0xFF;
        System.arraycopy(st, 0, stream, 3, st.length);
        assertEquals(List.of("7:36:3412"), decode(stream));
    }

    @Test
    void everySingleByteErrorIsRejected() {
        byte[] good = hex("FF FF 01 04 02 38 02 BE");
        for (int i = 2; i < good.length; i++) {
            byte[] bad = good.clone();
            bad[i] ^= 0x01;
            assertEquals(List.of(), decode(bad), "byte " + i);
        }
    }
}
