package org.parpe.serial.servo.wire;

/**
 * One decoded packet, reused by its decoder: valid only during the handler call. For an
 * instruction packet {@link #code} is the instruction; for a status packet it is
 * {@link PacketCodec#STATUS} on Dynamixel 2.0 (the error byte is then {@link #error}) and the error
 * byte itself on Feetech, whose status packets have no instruction field (see
 * {@link PacketCodec#statusError}). {@link #params} holds the parameters with stuffing removed.
 */
public final class Packet {
    /** Largest parameter block a decoder accepts. */
    public static final int MAX_PARAMS = 1024;

    /** Servo ID (or the broadcast ID). */
    public int id;
    /** Instruction, or the status marker / error byte (see the class comment). */
    public int code;
    /** Error byte of a Dynamixel 2.0 status packet (0 otherwise). */
    public int error;
    /** Parameters, {@code params[0 … length)}. */
    public final byte[] params = new byte[MAX_PARAMS];
    /** Number of parameters. */
    public int length;
    /** The packet as it was on the wire, {@code raw[0 … rawLength)}. */
    public final byte[] raw = new byte[2 * MAX_PARAMS + 16];
    /** Bytes of the packet on the wire. */
    public int rawLength;

    /** An unsigned little-endian value of {@code size} (1, 2 or 4) bytes at {@code off} of the parameters. */
    public int le(int off, int size) {
        return PacketCodec.le(params, off, size);
    }
}
