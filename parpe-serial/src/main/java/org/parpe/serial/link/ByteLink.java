package org.parpe.serial.link;

import java.io.IOException;

/**
 * A full-duplex byte stream to the bus. One thread may read while another writes; writes from
 * several threads must be serialised by the caller.
 */
public interface ByteLink extends AutoCloseable {

    /** Writes all {@code len} bytes; throws when the device is gone. */
    void write(byte[] b, int off, int len) throws IOException;

    /**
     * Reads what has arrived into {@code b}, waiting at most about a millisecond: returns the
     * number of bytes (0 when none came); throws when the device is gone or the link is closed.
     */
    int read(byte[] b) throws IOException;

    /**
     * Bytes written but not yet on the wire (the driver's output queue); the bus sends new
     * setpoints only when it is empty, so stale frames never queue up behind a slow line.
     */
    default int pendingOutput() {
        return 0;
    }

    /** A name for messages (the device path). */
    String name();

    /** Closes the link; a blocked {@link #read} ends with an exception. Idempotent. */
    @Override
    void close();
}
