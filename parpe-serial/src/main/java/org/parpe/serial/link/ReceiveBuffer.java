package org.parpe.serial.link;

/**
 * The bytes a decoder has received but not consumed yet, {@code bytes()[start() … end())}, the
 * same for every bus's decoder (G1 frames, Dynamixel and Feetech packets): received bytes are
 * appended, moved to the front when the end is reached, and consumed from the start as packets
 * are recognised or garbage is skipped. No allocation after construction; not thread-safe.
 */
public final class ReceiveBuffer {
    private final byte[] bytes;
    private int start;
    private int end;

    /** An empty buffer of {@code capacity} bytes (at least the longest packet). */
    public ReceiveBuffer(int capacity) {
        bytes = new byte[capacity];
    }

    /** The buffer's array, read from {@link #start()} to {@link #end()}. */
    public byte[] bytes() {
        return bytes;
    }

    /** Where the first byte not consumed is. */
    public int start() {
        return start;
    }

    /** Where the bytes received end. */
    public int end() {
        return end;
    }

    /** Bytes received but not consumed. */
    public int pending() {
        return end - start;
    }

    /**
     * Appends as many of {@code len} bytes of {@code data} from {@code off} as fit, first moving
     * what is pending to the front if the buffer's end is reached; returns how many it took.
     */
    public int append(byte[] data, int off, int len) {
        if (end == bytes.length) {
            System.arraycopy(bytes, start, bytes, 0, end - start);
            end -= start;
            start = 0;
        }
        int n = Math.min(len, bytes.length - end);
        System.arraycopy(data, off, bytes, end, n);
        end += n;
        return n;
    }

    /** Everything before {@code p} is consumed. */
    public void consumeTo(int p) {
        start = p;
    }

    /** Everything before {@code p} is consumed; once nothing is pending, the buffer starts again at its front. */
    public void settle(int p) {
        start = p;
        if (start == end) {
            clear();
        }
    }

    /** Drops everything pending. */
    public void clear() {
        start = 0;
        end = 0;
    }
}
