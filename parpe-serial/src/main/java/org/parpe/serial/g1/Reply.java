package org.parpe.serial.g1;


/**
 * A decoded PONG or STATUS, reused from transaction to transaction. For a PONG only
 * {@link #angle} and {@link #flags} are set.
 */
public final class Reply {
    /** Measured angle, degrees. */
    public double angle;
    /** Accelerometer x, y, z: −100…100. */
    public final int[] accel = new int[3];
    /** Touch bits ({@link Protocol.Touch}). */
    public int touch;
    /** Status flags ({@link Protocol.Flag}). */
    public int flags;
    /** Frames the module rejected by CRC since it started. */
    public int rxErrors;

    /** Fills this from a reply payload; false when the payload has the wrong length. */
    boolean decode(int cmd, byte[] b, int off, int len) {
        if (Command.PONG.isReply(cmd, len)) {
            flags = b[off + 2] & 0xFF;
            angle = Protocol.fromWire(FrameHandler.i16(b, off + 3));
            return true;
        }
        if (Command.STATUS.isReply(cmd, len)) {
            angle = Protocol.fromWire(FrameHandler.i16(b, off));
            accel[0] = b[off + 2];
            accel[1] = b[off + 3];
            accel[2] = b[off + 4];
            touch = b[off + 5] & 0xFF;
            flags = b[off + 6] & 0xFF;
            rxErrors = FrameHandler.u16(b, off + 7);
            return true;
        }
        return false;
    }

    /** Copies every field from {@code other}. */
    void copyFrom(Reply other) {
        angle = other.angle;
        System.arraycopy(other.accel, 0, accel, 0, 3);
        touch = other.touch;
        flags = other.flags;
        rxErrors = other.rxErrors;
    }
}
