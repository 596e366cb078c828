package org.parpe.serial.servo.wire;

/**
 * The CRC of Dynamixel Protocol 2.0 as the ROBOTIS e-Manual defines it: CRC-16 with polynomial
 * 0x8005, initial value 0, most significant bit first, no final xor (also known as
 * CRC-16/BUYPASS), over every byte of the packet from the header up to the CRC field. Table driven.
 */
public final class Dxl2Crc {
    private static final int[] TABLE = new int[256];

    static {
        for (int i = 0; i < 256; i++) {
            int c = i << 8;
            for (int b = 0; b < 8; b++) {
                c = (c & 0x8000) != 0 ? (c << 1) ^ 0x8005 : c << 1;
            }
            TABLE[i] = c & 0xFFFF;
        }
    }

    private Dxl2Crc() {
    }

    /** The CRC of {@code len} bytes of {@code b} from {@code off}. */
    public static int of(byte[] b, int off, int len) {
        int crc = 0;
        for (int i = off, end = off + len; i < end; i++) {
            crc = ((crc << 8) ^ TABLE[((crc >>> 8) ^ b[i]) & 0xFF]) & 0xFFFF;
        }
        return crc;
    }
}
