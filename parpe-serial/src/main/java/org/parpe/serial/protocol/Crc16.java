package org.parpe.serial.protocol;

/**
 * CRC-16/CCITT-FALSE (polynomial 0x1021, initial value 0xFFFF, no reflection): detects every
 * error burst of up to 16 bits, so a single corrupted byte never passes. Table driven; a PIC
 * can compute it bit by bit.
 */
public final class Crc16 {
    private static final int[] TABLE = new int[256];

    static {
        for (int i = 0; i < 256; i++) {
            int c = i << 8;
            for (int b = 0; b < 8; b++) {
                c = (c & 0x8000) != 0 ? (c << 1) ^ 0x1021 : c << 1;
            }
            TABLE[i] = c & 0xFFFF;
        }
    }

    private Crc16() {
    }

    /** The CRC of {@code len} bytes of {@code buf} from {@code off}. */
    public static int of(byte[] buf, int off, int len) {
        int crc = 0xFFFF;
        for (int i = off, end = off + len; i < end; i++) {
            crc = ((crc << 8) ^ TABLE[((crc >>> 8) ^ buf[i]) & 0xFF]) & 0xFFFF;
        }
        return crc;
    }
}
