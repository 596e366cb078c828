package org.parpe.serial.dynamixel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.parpe.serial.servo.wire.Packet;
import org.parpe.serial.servo.wire.PacketCodec;
import org.parpe.serial.servo.wire.PacketDecoder;

/**
 * Dynamixel Protocol 2.0 packets byte for byte against the examples printed in the ROBOTIS
 * e-Manual ("DYNAMIXEL Protocol 2.0", sections Ping, Read, Write, Sync Read, Sync Write), in both
 * directions: our encoder builds them and our decoder accepts them.
 */
public class Dxl2CodecTest {
    final Dxl2Codec codec = new Dxl2Codec();
    final byte[] out = new byte[codec.bufferSize()];

    /** Bytes of hex pairs separated by blanks (the manuals' way of writing packets); FeetechCodecTest uses it too. */
    public static byte[] hex(String s) {
        String[] w = s.trim().split("\\s+");
        byte[] b = new byte[w.length];
        for (int i = 0; i < w.length; i++) {
            b[i] = (byte) Integer.parseInt(w[i], 16);
        }
        return b;
    }

    public static byte[] params(int... v) {
        byte[] b = new byte[v.length];
        for (int i = 0; i < v.length; i++) {
            b[i] = (byte) v[i];
        }
        return b;
    }

    byte[] instruction(int id, int inst, int... p) {
        return Arrays.copyOf(out, codec.instruction(out, id, inst, params(p), p.length));
    }

    byte[] status(int id, int error, int... p) {
        return Arrays.copyOf(out, codec.status(out, id, error, params(p), p.length));
    }

    List<String> decode(byte[] bytes) {
        List<String> got = new ArrayList<>();
        PacketDecoder d = codec.decoder(p -> got.add(p.id + ":" + Integer.toHexString(p.code) + ":" + p.error + ":"
                + hexOf(Arrays.copyOf(p.params, p.length))));
        d.feed(bytes, 0, bytes.length);
        return got;
    }

    public static String hexOf(byte[] b) {
        StringBuilder s = new StringBuilder();
        for (byte x : b) {
            s.append(String.format("%02X", x & 0xFF));
        }
        return s.toString();
    }

    @Test
    void pingOfId1AndItsStatusPacketAsInTheManual() {
        assertArrayEquals(hex("FF FF FD 00 01 03 00 01 19 4E"), instruction(1, PacketCodec.PING));
        // XM430-W210: model number 1030 (0x0406), firmware version 0x26.
        byte[] st = hex("FF FF FD 00 01 07 00 55 00 06 04 26 65 5D");
        assertArrayEquals(st, status(1, 0, 0x06, 0x04, 0x26));
        assertEquals(List.of("1:55:0:060426"), decode(st));
    }

    @Test
    void broadcastPingAsInTheManual() {
        assertArrayEquals(hex("FF FF FD 00 FE 03 00 01 31 42"), instruction(0xFE, PacketCodec.PING));
    }

    @Test
    void readPresentPositionAsInTheManual() {
        assertArrayEquals(hex("FF FF FD 00 01 07 00 02 84 00 04 00 1D 15"), instruction(1, PacketCodec.READ,
                0x84, 0x00, 0x04, 0x00));
        byte[] st = hex("FF FF FD 00 01 08 00 55 00 A6 00 00 00 8C C0");
        assertArrayEquals(st, status(1, 0, 0xA6, 0, 0, 0));
        assertEquals(List.of("1:55:0:A6000000"), decode(st));
    }

    @Test
    void writeGoalPositionAsInTheManual() {
        assertArrayEquals(hex("FF FF FD 00 01 09 00 03 74 00 00 02 00 00 CA 89"), instruction(1, PacketCodec.WRITE,
                0x74, 0x00, 0x00, 0x02, 0x00, 0x00));
        assertArrayEquals(hex("FF FF FD 00 01 04 00 55 00 A1 0C"), status(1, 0));
    }

    @Test
    void syncReadAndSyncWriteAsInTheManual() {
        assertArrayEquals(hex("FF FF FD 00 FE 09 00 82 84 00 04 00 01 02 CE FA"), instruction(0xFE,
                PacketCodec.SYNC_READ, 0x84, 0x00, 0x04, 0x00, 1, 2));
        assertArrayEquals(hex("FF FF FD 00 FE 11 00 83 74 00 04 00 01 96 00 00 00 02 AA 00 00 00 82 87"),
                instruction(0xFE, PacketCodec.SYNC_WRITE, 0x74, 0x00, 0x04, 0x00, 1, 0x96, 0, 0, 0, 2, 0xAA, 0, 0, 0));
    }

    @Test
    void fastSyncReadAndItsOneStatusPacketAsInTheManual() {
        // ROBOTIS e-Manual, "DYNAMIXEL Protocol 2.0", Fast Sync Read (0x8A), example: IDs 3, 7 and 4
        // answer a read of Present Position (132, 4 bytes) = 166, 2 079 and 1 023 with ONE status
        // packet from ID 0xFE, LEN 25; each device's block is its error, its ID, its data and the
        // CRC of the packet up to there, the last block's CRC being the packet's.
        assertArrayEquals(hex("FF FF FD 00 FE 0A 00 8A 84 00 04 00 03 07 04 20 F2"), instruction(0xFE,
                PacketCodec.FAST_SYNC_READ, 0x84, 0x00, 0x04, 0x00, 3, 7, 4));
        byte[] st = hex("FF FF FD 00 FE 19 00 55 00 03 A6 00 00 00 84 08 00 07 1F 08 00 00 16 CA"
                + " 00 04 FF 03 00 00 D1 9E");
        byte[] blocks = params(0, 3, 0xA6, 0, 0, 0, 0, 7, 0x1F, 0x08, 0, 0, 0, 4, 0xFF, 0x03, 0, 0);
        assertArrayEquals(st, Arrays.copyOf(out, codec.fastStatus(out, blocks, 4, 3, 3)));
        List<Packet> got = new ArrayList<>();
        codec.decoder(p -> got.add(copy(p))).feed(st, 0, st.length);
        assertEquals(1, got.size());
        Packet p = got.get(0);
        assertEquals(0xFE, p.id);
        assertEquals(3, Dxl2Codec.fastDevices(p.length, 4));
        int[] ids = new int[3];
        int[] positions = new int[3];
        for (int k = 0; k < 3; k++) {
            ids[k] = p.params[Dxl2Codec.fastIdAt(k, 4)];
            positions[k] = p.le(Dxl2Codec.fastIdAt(k, 4) + 1, 4);
        }
        assertArrayEquals(new int[] {3, 7, 4}, ids);
        assertArrayEquals(new int[] {166, 2079, 1023}, positions);
    }

    @Test
    void aFastSyncReadStatusIsNotStuffed() {
        // The devices build the packet one block after another, so none can stuff what the others
        // sent: data FF FF FD FD arrives as it is (DynamixelSDK, GroupFastSyncRead::rxPacket
        // receives it with stuffing removal skipped). A partial packet (the chain broken after the
        // first device) never completes.
        byte[] blocks = params(0, 5, 0xFF, 0xFF, 0xFD, 0xFD, 0, 6, 1, 2, 3, 4);
        byte[] st = Arrays.copyOf(out, codec.fastStatus(out, blocks, 4, 2, 2));
        List<Packet> got = new ArrayList<>();
        PacketDecoder d = codec.decoder(p -> got.add(copy(p)));
        d.feed(st, 0, st.length);
        assertEquals(1, got.size());
        assertEquals(0xFDFDFFFF, got.get(0).le(1, 4));
        assertEquals(0x04030201, got.get(0).le(Dxl2Codec.fastIdAt(1, 4) + 1, 4));
        got.clear();
        byte[] partial = Arrays.copyOf(out, codec.fastStatus(out, blocks, 4, 2, 1));
        d.feed(partial, 0, partial.length);
        d.idle();
        assertEquals(List.of(), got);
    }

    static Packet copy(Packet p) {
        Packet c = new Packet();
        c.id = p.id;
        c.code = p.code;
        c.error = p.error;
        c.length = p.length;
        System.arraycopy(p.params, 0, c.params, 0, p.length);
        return c;
    }

    @Test
    void stuffingInsertsFdAfterEveryHeaderPatternAndTheDecoderRemovesIt() {
        byte[] p = instruction(1, PacketCodec.WRITE, 0xFF, 0xFF, 0xFD, 0x01, 0xFF, 0xFF, 0xFD, 0xFD);
        // INST + 8 params + 2 stuffed bytes + CRC = 13.
        assertEquals(13, p[5] & 0xFF);
        byte[] body = Arrays.copyOfRange(p, 8, p.length - 2);
        assertArrayEquals(hex("FF FF FD FD 01 FF FF FD FD FD"), body);
        assertEquals(List.of("1:3:0:FFFFFD01FFFFFDFD"), decode(p));
    }

    @Test
    void statusErrorByteWithAlertBit() {
        byte[] st = status(3, Dxl2Codec.ERROR_ALERT | Dxl2Codec.ERROR_DATA_LIMIT, 1, 2, 3, 4);
        assertEquals(List.of("3:55:134:01020304"), decode(st));
    }

    @Test
    void everySingleByteErrorIsRejectedAndTheNextPacketStillDecodes() {
        byte[] good = hex("FF FF FD 00 01 08 00 55 00 A6 00 00 00 8C C0");
        for (int i = 0; i < good.length; i++) {
            for (int flip = 1; flip < 256; flip += 37) {
                byte[] bad = good.clone();
                bad[i] ^= (byte) flip;
                byte[] stream = new byte[bad.length + good.length];
                System.arraycopy(bad, 0, stream, 0, bad.length);
                System.arraycopy(good, 0, stream, bad.length, good.length);
                List<String> got = new ArrayList<>();
                PacketDecoder d = codec.decoder(pk -> got.add(pk.id + ":" + hexOf(Arrays.copyOf(pk.params, pk.length))));
                d.feed(stream, 0, stream.length);
                d.idle();
                assertEquals("1:A6000000", got.get(got.size() - 1), "byte " + i + " xor " + flip);
                assertEquals(1, got.stream().filter(s -> s.equals("1:A6000000")).count(), "byte " + i + " xor " + flip);
            }
        }
    }

    @Test
    void bytesArrivingOneAtATimeDecodeTheSame() {
        byte[] st = hex("FF FF FD 00 01 07 00 55 00 06 04 26 65 5D");
        List<String> got = new ArrayList<>();
        PacketDecoder d = codec.decoder(p -> got.add(p.id + ":" + hexOf(Arrays.copyOf(p.params, p.length))));
        for (byte b : st) {
            d.feed(new byte[] {b}, 0, 1);
        }
        assertEquals(List.of("1:060426"), got);
    }
}
