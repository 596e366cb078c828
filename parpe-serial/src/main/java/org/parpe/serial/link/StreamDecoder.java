package org.parpe.serial.link;

/**
 * A decoder of the bytes a link delivers (G1 frames, Dynamixel or Feetech packets): fed the
 * bytes as they come, and told when the line has gone quiet in the middle of a packet.
 */
public interface StreamDecoder {

    /** Takes {@code len} received bytes of {@code data} from {@code off}. */
    void feed(byte[] data, int off, int len);

    /** How many bytes of an unfinished packet it holds. */
    int pending();

    /** The line went quiet: an unfinished packet will not be completed; drop it and resynchronise. */
    void idle();
}
