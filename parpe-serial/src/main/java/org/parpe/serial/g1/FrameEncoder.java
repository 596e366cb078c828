package org.parpe.serial.g1;

import org.parpe.serial.bus.Crc16;

/**
 * Builds frames in one reused buffer, without allocating: {@link #begin}, then {@code put…}
 * for the payload, then {@link #finish}, which fills in length and CRC and returns the frame
 * length; the frame is {@code buffer()[0 … length)}. Not thread-safe: one encoder per writer.
 */
public final class FrameEncoder {
    private final byte[] buf = new byte[Protocol.MAX_FRAME];
    private int pos;

    /** The buffer holding the last frame built. */
    public byte[] buffer() {
        return buf;
    }

    /** Starts a frame to {@code addr} with command {@code cmd}. */
    public FrameEncoder begin(int addr, Command cmd) {
        buf[0] = (byte) Protocol.SYNC1;
        buf[1] = (byte) Protocol.SYNC2;
        buf[2] = (byte) addr;
        buf[5] = (byte) cmd.code();
        pos = Protocol.HEADER;
        return this;
    }

    /** Appends an unsigned byte. */
    public FrameEncoder putU8(int v) {
        checkRoom(1);
        buf[pos++] = (byte) v;
        return this;
    }

    /** Appends a 16-bit value, little-endian. */
    public FrameEncoder putU16(int v) {
        checkRoom(2);
        buf[pos++] = (byte) v;
        buf[pos++] = (byte) (v >>> 8);
        return this;
    }

    /** Ends the frame: writes length and CRC, returns the frame length. */
    public int finish() {
        int len = pos - Protocol.HEADER;
        buf[3] = (byte) len;
        buf[4] = (byte) (len >>> 8);
        int crc = Crc16.CCITT_FALSE.of(buf, 2, pos - 2);
        buf[pos++] = (byte) (crc >>> 8);
        buf[pos++] = (byte) crc;
        return pos;
    }

    /** A frame without payload. */
    public int simple(int addr, Command cmd) {
        return begin(addr, cmd).finish();
    }

    /**
     * A broadcast SETPOINTS frame for modules {@code first … first+count−1}; {@code wire} holds
     * their wire angles (hundredths of a degree, or {@link Protocol#NO_CHANGE}).
     */
    public int setpoints(int seq, int first, short[] wire, int count) {
        if (count < 1 || 3 + 2 * count > Protocol.MAX_PAYLOAD) {
            throw new IllegalArgumentException("a setpoint frame covers 1.." + (Protocol.MAX_PAYLOAD - 3) / 2
                    + " modules, got " + count);
        }
        begin(Protocol.BROADCAST, Command.SETPOINTS).putU16(seq).putU8(first);
        for (int i = 0; i < count; i++) {
            int v = wire[i];
            buf[pos++] = (byte) v;
            buf[pos++] = (byte) (v >>> 8);
        }
        return finish();
    }

    private void checkRoom(int n) {
        if (pos + n > Protocol.HEADER + Protocol.MAX_PAYLOAD) {
            throw new IllegalStateException("payload longer than " + Protocol.MAX_PAYLOAD + " bytes");
        }
    }
}
