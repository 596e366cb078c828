package org.parpe.serial.link;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import java.util.function.LongSupplier;

/**
 * How a host ends its link, the same for every bus (G1's {@code BusMaster}, the other
 * protocols' {@code PacketPort}): what was written must reach the far end before the port
 * closes, since closing may discard what is still queued (the final HOLD, an emergency stop)
 * or flush what the other side has not read yet (a pty's queue, a USB adapter's buffer).
 */
public final class LinkCloser {
    /** How long the far end is given after the last write to read it, in milliseconds. */
    public static final long LINGER_MS = 50;

    private LinkCloser() {
    }

    /**
     * Waits up to {@code timeoutMs} until every byte written has left {@code link}'s output
     * queue, or until {@code failed} says the link has failed.
     */
    public static void drain(ByteLink link, BooleanSupplier failed, long timeoutMs) {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        while (!failed.getAsBoolean() && link.pendingOutput() > 0 && System.nanoTime() < deadline) {
            LockSupport.parkNanos(200_000);
        }
    }

    /**
     * Lets queued bytes leave (at most 250 ms), gives the far end {@value #LINGER_MS} ms after
     * the last write ({@code lastWriteNanos}, a {@link System#nanoTime()}), then stops the reader
     * ({@code stopReader} clears its running flag), closes the link and waits up to a second for
     * the {@code reader} thread to end. A failed link is closed at once.
     */
    public static void close(ByteLink link, BooleanSupplier failed, LongSupplier lastWriteNanos, Runnable stopReader,
                             Thread reader) {
        drain(link, failed, 250);
        long linger = lastWriteNanos.getAsLong() + TimeUnit.MILLISECONDS.toNanos(LINGER_MS) - System.nanoTime();
        if (linger > 0 && !failed.getAsBoolean()) {
            LockSupport.parkNanos(linger);
        }
        stopReader.run();
        link.close();
        try {
            reader.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
