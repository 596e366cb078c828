package org.parpe.serial.bus;

/**
 * A table-driven CRC-16, most significant bit first, no reflection, no final xor: the one CRC
 * routine of every bus protocol, which differ only in polynomial and initial value.
 * <ul>
 * <li>{@link #CCITT_FALSE}: polynomial 0x1021, initial value 0xFFFF, the G1 frame check; it
 * detects every error burst of up to 16 bits, so a single corrupted byte never passes, and a PIC
 * can compute it bit by bit.</li>
 * <li>{@link #DXL2}: polynomial 0x8005, initial value 0 (CRC-16/BUYPASS), the CRC of Dynamixel
 * Protocol 2.0 as the ROBOTIS e-Manual defines it, over every byte of the packet from the header
 * up to the CRC field.</li>
 * </ul>
 */
public final class Crc16 {
    /** CRC-16/CCITT-FALSE: the G1 frame check. */
    public static final Crc16 CCITT_FALSE = new Crc16(0x1021, 0xFFFF);
    /** CRC-16/BUYPASS: the Dynamixel Protocol 2.0 packet check. */
    public static final Crc16 DXL2 = new Crc16(0x8005, 0);

    private final int[] table = new int[256];
    private final int polynomial;
    private final int initial;

    private Crc16(int polynomial, int initial) {
        this.polynomial = polynomial;
        this.initial = initial;
        for (int i = 0; i < 256; i++) {
            int c = i << 8;
            for (int b = 0; b < 8; b++) {
                c = (c & 0x8000) != 0 ? (c << 1) ^ polynomial : c << 1;
            }
            table[i] = c & 0xFFFF;
        }
    }

    /** The generator polynomial (without its x^16 term), for code generated elsewhere. */
    public int polynomial() {
        return polynomial;
    }

    /** The CRC of {@code len} bytes of {@code buf} from {@code off}. */
    public int of(byte[] buf, int off, int len) {
        int[] t = table;
        int crc = initial;
        for (int i = off, end = off + len; i < end; i++) {
            crc = ((crc << 8) ^ t[((crc >>> 8) ^ buf[i]) & 0xFF]) & 0xFFFF;
        }
        return crc;
    }
}
