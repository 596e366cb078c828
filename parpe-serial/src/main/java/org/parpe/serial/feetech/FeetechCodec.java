package org.parpe.serial.feetech;

import org.parpe.serial.servo.wire.Packet;
import org.parpe.serial.servo.wire.PacketCodec;
import org.parpe.serial.servo.wire.PacketDecoder;
import org.parpe.serial.servo.wire.PacketHandler;

/**
 * Feetech STS/SCS packets (Feetech's bus servo communication protocol manual, the same layout
 * as Dynamixel Protocol 1.0): {@code FF FF ID LEN INST PARAM… CHK}, where LEN is the number of
 * parameters + 2 and CHK = ~(ID + LEN + INST + PARAM…) & 0xFF. A status packet carries the
 * servo's error byte where the instruction would be. Multi-byte values: STS servos are
 * little-endian, SCS servos big-endian. Status bits: 0 voltage, 1 sensor, 2 overheating,
 * 3 overcurrent, 4 angle, 5 overload.
 */
public final class FeetechCodec implements PacketCodec {
    private static final int HEAD = 4;
    /** Error bit: overheating. */
    public static final int ERROR_OVERHEAT = 0x04;
    /** Error bit: overload. */
    public static final int ERROR_OVERLOAD = 0x20;

    @Override
    public int instruction(byte[] out, int id, int instruction, byte[] params, int len) {
        return build(out, id, instruction, params, len);
    }

    @Override
    public int status(byte[] out, int id, int error, byte[] params, int len) {
        return build(out, id, error, params, len);
    }

    private static int build(byte[] out, int id, int code, byte[] params, int len) {
        if (len < 0 || len > 253) {
            throw new IllegalArgumentException("parameters must be 0..253 bytes, got " + len);
        }
        out[0] = (byte) 0xFF;
        out[1] = (byte) 0xFF;
        out[2] = (byte) id;
        out[3] = (byte) (len + 2);
        out[4] = (byte) code;
        System.arraycopy(params, 0, out, HEAD + 1, len);
        out[HEAD + 1 + len] = (byte) checksum(out, 2, len + 3);
        return HEAD + 2 + len;
    }

    /** The one's complement of the low byte of the sum of {@code len} bytes from {@code off}. */
    public static int checksum(byte[] b, int off, int len) {
        int sum = 0;
        for (int i = off; i < off + len; i++) {
            sum += b[i] & 0xFF;
        }
        return ~sum & 0xFF;
    }

    @Override
    public PacketDecoder decoder(PacketHandler handler) {
        return new Decoder(handler);
    }

    @Override
    public int statusError(Packet p) {
        return p.code;
    }

    /**
     * 1-byte addresses, a Ping reply without parameters, status packets not marked, one Ping per
     * servo, no error numbers and no watchdog.
     */
    private static final Traits TRAITS = new Traits("Feetech", 1, 0, false, false, false, false);

    @Override
    public Traits traits() {
        return TRAITS;
    }

    /** The instructions of Feetech's protocol manual: none of Dynamixel 2.0's additions. */
    @Override
    public boolean knows(int instruction) {
        return switch (instruction) {
            case PING, READ, WRITE, REG_WRITE, ACTION, SYNC_READ, SYNC_WRITE -> true;
            default -> false;
        };
    }

    /** The servo's status bits; there are no error numbers. */
    @Override
    public int statusByte(int hardwareError, int errorNumber) {
        return hardwareError;
    }

    @Override
    public boolean answers(int level, boolean read) {
        return read || level >= 1;
    }

    /** Every bit of the status byte is a fault of the servo. */
    @Override
    public boolean faulty(int statusError) {
        return statusError != 0;
    }

    @Override
    public String packetError(int statusError) {
        return null;
    }

    @Override
    public int packetLength(int params) {
        return HEAD + 2 + params;
    }

    /** The receiving side: header search and checksum. */
    private static final class Decoder extends PacketDecoder {
        Decoder(PacketHandler handler) {
            super(handler);
        }

        @Override
        protected int tryPacket(int p, int avail, Packet out) {
            if ((buf[p] & 0xFF) != 0xFF) {
                return NO_HEADER;
            }
            if (avail < 2) {
                return INCOMPLETE;
            }
            // A third FF is no ID: the header starts one byte later.
            if ((buf[p + 1] & 0xFF) != 0xFF) {
                return NO_HEADER;
            }
            if (avail < HEAD) {
                return INCOMPLETE;
            }
            int id = buf[p + 2] & 0xFF;
            int length = buf[p + 3] & 0xFF;
            if (id == 0xFF || length < 2) {
                return NO_HEADER;
            }
            int total = HEAD + length;
            if (avail < total) {
                return INCOMPLETE;
            }
            if (checksum(buf, p + 2, length + 1) != (buf[p + total - 1] & 0xFF)) {
                return BAD_CHECK;
            }
            out.id = id;
            out.code = buf[p + HEAD] & 0xFF;
            out.error = 0;
            out.length = length - 2;
            System.arraycopy(buf, p + HEAD + 1, out.params, 0, out.length);
            return total;
        }
    }
}
