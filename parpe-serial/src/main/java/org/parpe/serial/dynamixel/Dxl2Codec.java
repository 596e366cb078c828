package org.parpe.serial.dynamixel;

import org.parpe.serial.bus.Crc16;
import org.parpe.serial.servo.wire.Packet;
import org.parpe.serial.servo.wire.PacketCodec;
import org.parpe.serial.servo.wire.PacketDecoder;
import org.parpe.serial.servo.wire.PacketHandler;

/**
 * Dynamixel Protocol 2.0 packets (ROBOTIS e-Manual, "Protocol 2.0"):
 * {@code FF FF FD 00 ID LEN_L LEN_H INST PARAM… CRC_L CRC_H}, where LEN counts the instruction,
 * the (stuffed) parameters and the CRC. A status packet has INST {@code 0x55} followed by the
 * error byte. Byte stuffing: wherever {@code FF FF FD} appears from the instruction on, a
 * {@code FD} is inserted after it, so the header can never appear inside a packet; LEN and the
 * CRC cover the stuffed bytes, and the receiver removes the extra {@code FD}. The error numbers
 * (low 7 bits of the error byte) 1…7 are result fail, instruction, CRC, data range, data length,
 * data limit and access error. The one status packet that answers a Fast Sync Read comes from
 * the broadcast ID and is not stuffed ({@link #fastStatus}).
 */
public final class Dxl2Codec implements PacketCodec {
    /** Bytes of header, ID and length. */
    private static final int HEAD = 7;
    private static final byte[] HEADER = {(byte) 0xFF, (byte) 0xFF, (byte) 0xFD, 0x00};
    /** Error byte bit: the servo has a hardware error (read Hardware Error Status). */
    public static final int ERROR_ALERT = 0x80;
    /** Error number: unknown instruction, or Action without Reg Write. */
    public static final int ERROR_INSTRUCTION = 0x02;
    /** Error number: a value outside the limits set in the control table. */
    public static final int ERROR_DATA_LIMIT = 0x06;
    /** Error number: a read-only or unknown address, or a write to the EEPROM with torque on. */
    public static final int ERROR_ACCESS = 0x07;

    private final byte[] stuffed = new byte[2 * Packet.MAX_PARAMS + 8];

    @Override
    public int instruction(byte[] out, int id, int instruction, byte[] params, int len) {
        return build(out, id, instruction, -1, params, len);
    }

    @Override
    public int status(byte[] out, int id, int error, byte[] params, int len) {
        return build(out, id, STATUS, error, params, len);
    }

    /** Not thread-safe: one codec per writer (it reuses a scratch buffer). */
    private int build(byte[] out, int id, int inst, int error, byte[] params, int len) {
        if (len < 0 || len > Packet.MAX_PARAMS) {
            throw new IllegalArgumentException("parameters must be 0.." + Packet.MAX_PARAMS + " bytes, got " + len);
        }
        int n = 0;
        stuffed[n++] = (byte) inst;
        if (error >= 0) {
            stuffed[n++] = (byte) error;
        }
        for (int i = 0; i < len; i++) {
            stuffed[n++] = params[i];
            if (n >= 3 && stuffed[n - 1] == (byte) 0xFD && stuffed[n - 2] == (byte) 0xFF && stuffed[n - 3] == (byte) 0xFF) {
                stuffed[n++] = (byte) 0xFD;
            }
        }
        out[0] = (byte) 0xFF;
        out[1] = (byte) 0xFF;
        out[2] = (byte) 0xFD;
        out[3] = 0;
        out[4] = (byte) id;
        int length = n + 2;
        out[5] = (byte) length;
        out[6] = (byte) (length >>> 8);
        System.arraycopy(stuffed, 0, out, HEAD, n);
        int crc = Crc16.DXL2.of(out, 0, HEAD + n);
        out[HEAD + n] = (byte) crc;
        out[HEAD + n + 1] = (byte) (crc >>> 8);
        return HEAD + n + 2;
    }

    /**
     * The status packet that answers a Fast Sync Read (e-Manual, Protocol 2.0, Fast Sync Read):
     * ID 0xFE, LEN for {@code n} devices, then per device its error, its ID, its {@code size}
     * data bytes and the CRC of the packet up to there (the last is the packet's CRC). The
     * devices send it one block after another, so it is not stuffed. {@code blocks} holds error,
     * ID and data of each device in turn; only the first {@code sent} blocks are written (fewer
     * than {@code n} when the chain broke: a packet that never completes). Returns its length.
     */
    public int fastStatus(byte[] out, byte[] blocks, int size, int n, int sent) {
        int length = 1 + n * (size + 4);
        if (size < 0 || sent > n || HEAD + length > out.length) {
            throw new IllegalArgumentException("a Fast Sync Read status of " + n + " blocks of " + size
                    + " bytes does not fit " + out.length + " bytes");
        }
        System.arraycopy(HEADER, 0, out, 0, HEADER.length);
        out[4] = (byte) BROADCAST;
        out[5] = (byte) length;
        out[6] = (byte) (length >>> 8);
        out[HEAD] = (byte) STATUS;
        int pos = HEAD + 1;
        for (int k = 0; k < sent; k++) {
            System.arraycopy(blocks, k * (size + 2), out, pos, size + 2);
            pos += size + 2;
            int crc = Crc16.DXL2.of(out, 0, pos);
            out[pos++] = (byte) crc;
            out[pos++] = (byte) (crc >>> 8);
        }
        return pos;
    }

    /**
     * The devices whose blocks of {@code size} data bytes a Fast Sync Read status with
     * {@code params} parameters carries (the decoder keeps the first device's error in
     * {@link Packet#error} and drops the last CRC), or −1 when no number of blocks fits.
     */
    public static int fastDevices(int params, int size) {
        return (params + 3) % (size + 4) == 0 ? (params + 3) / (size + 4) : -1;
    }

    /**
     * Where device {@code k}'s ID lies among a Fast Sync Read status's parameters: its data
     * follows, its error byte (for {@code k} > 0) comes before.
     */
    public static int fastIdAt(int k, int size) {
        return k * (size + 4);
    }

    @Override
    public PacketDecoder decoder(PacketHandler handler) {
        return new Decoder(handler);
    }

    @Override
    public int statusError(Packet p) {
        return p.error;
    }

    /** Status error numbers 1…7 (e-Manual, Protocol 2.0, Status Packet: Error). */
    private static final String[] PACKET_ERRORS = {"result fail", "instruction error", "CRC error",
        "data range error", "data length error", "data limit error", "access error"};

    /**
     * 2-byte addresses, a Ping reply of model number and firmware (3 parameters), status packets
     * marked by their instruction field, a broadcast Ping, error numbers and a Bus Watchdog.
     */
    private static final Traits TRAITS = new Traits("Dynamixel", 2, 3, true, true, true, true);

    @Override
    public Traits traits() {
        return TRAITS;
    }

    /** Every instruction of {@link PacketCodec}. */
    @Override
    public boolean knows(int instruction) {
        return switch (instruction) {
            case PING, READ, WRITE, REG_WRITE, ACTION, REBOOT, SYNC_READ, SYNC_WRITE, FAST_SYNC_READ, BULK_READ,
                 BULK_WRITE -> true;
            default -> false;
        };
    }

    /** The alert bit when the servo has a hardware error, and the error number. */
    @Override
    public int statusByte(int hardwareError, int errorNumber) {
        return (hardwareError != 0 ? ERROR_ALERT : 0) | errorNumber;
    }

    @Override
    public boolean answers(int level, boolean read) {
        return level >= 2 || read && level >= 1;
    }

    /** Only with the alert bit: the error number in the low bits is about the packet. */
    @Override
    public boolean faulty(int statusError) {
        return (statusError & ERROR_ALERT) != 0;
    }

    @Override
    public String packetError(int statusError) {
        int number = statusError & 0x7F;
        return number >= 1 && number <= PACKET_ERRORS.length ? PACKET_ERRORS[number - 1] : null;
    }

    @Override
    public int packetLength(int params) {
        return HEAD + 1 + params + 2;
    }

    /** The receiving side: header search, CRC check, stuffing removed. */
    private static final class Decoder extends PacketDecoder {
        Decoder(PacketHandler handler) {
            super(handler);
        }

        @Override
        protected int tryPacket(int p, int avail, Packet out) {
            for (int i = 0; i < HEADER.length; i++) {
                if (i >= avail) {
                    return INCOMPLETE;
                }
                if (buf[p + i] != HEADER[i]) {
                    return NO_HEADER;
                }
            }
            if (avail < HEAD) {
                return INCOMPLETE;
            }
            int length = (buf[p + 5] & 0xFF) | (buf[p + 6] & 0xFF) << 8;
            if (length < 3 || length > 2 * Packet.MAX_PARAMS + 4) {
                return NO_HEADER;
            }
            int total = HEAD + length;
            if (avail < total) {
                return INCOMPLETE;
            }
            int crc = Crc16.DXL2.of(buf, p, total - 2);
            if (crc != ((buf[p + total - 2] & 0xFF) | (buf[p + total - 1] & 0xFF) << 8)) {
                return BAD_CHECK;
            }
            out.id = buf[p + 4] & 0xFF;
            out.code = buf[p + HEAD] & 0xFF;
            int from = p + HEAD + 1;
            out.error = 0;
            if (out.code == STATUS) {
                if (length < 4) {
                    return BAD_CHECK;
                }
                out.error = buf[from++] & 0xFF;
            }
            // A status from the broadcast ID answers a Fast Sync Read: built by several devices
            // in turn, it is not stuffed.
            boolean stuffed = out.code != STATUS || out.id != BROADCAST;
            int n = 0;
            for (int i = from, end = p + total - 2; i < end; i++) {
                // Unstuff: the FD after FF FF FD was added by the sender.
                if (stuffed && buf[i] == (byte) 0xFD && i - 3 >= p + HEAD && buf[i - 1] == (byte) 0xFD
                        && buf[i - 2] == (byte) 0xFF && buf[i - 3] == (byte) 0xFF) {
                    continue;
                }
                if (n == Packet.MAX_PARAMS) {
                    return NO_HEADER;
                }
                out.params[n++] = buf[i];
            }
            out.length = n;
            return total;
        }
    }
}
