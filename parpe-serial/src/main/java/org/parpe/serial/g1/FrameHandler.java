package org.parpe.serial.g1;

/** Receives the frames a {@link FrameDecoder} recognises. */
@FunctionalInterface
public interface FrameHandler {

    /**
     * One valid frame. The payload is {@code buf[off … off+len)} and is only valid during the
     * call: the decoder reuses its buffer.
     */
    void onFrame(int addr, int cmd, byte[] buf, int off, int len);

    /** Reads an unsigned 16-bit little-endian value. */
    static int u16(byte[] b, int off) {
        return (b[off] & 0xFF) | (b[off + 1] & 0xFF) << 8;
    }

    /** Reads a signed 16-bit little-endian value. */
    static int i16(byte[] b, int off) {
        return (short) u16(b, off);
    }
}
