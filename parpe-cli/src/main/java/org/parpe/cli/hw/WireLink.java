package org.parpe.cli.hw;

import java.io.IOException;
import java.util.concurrent.locks.LockSupport;
import org.parpe.serial.link.ByteLink;

/**
 * A link that drains like a UART at a given baud rate (ten bits per byte): writes return at once
 * and {@link #pendingOutput()} shows the bytes still "on their way", as the kernel's output queue
 * of a real port does. Used by the benchmark to measure the driver against the wire limit.
 */
final class WireLink implements ByteLink {
    private final ByteLink inner;
    private final double nanosPerByte;
    private long wireFreeAt;

    WireLink(ByteLink inner, int baud) {
        this.inner = inner;
        this.nanosPerByte = 10e9 / baud;
    }

    @Override
    public synchronized void write(byte[] b, int off, int len) throws IOException {
        long now = System.nanoTime();
        wireFreeAt = Math.max(now, wireFreeAt) + (long) (len * nanosPerByte);
        // The far end sees the bytes when the last one has crossed the wire.
        long wait = wireFreeAt - now;
        inner.write(b, off, len);
        if (wait > 5_000_000) {
            LockSupport.parkNanos(wait - 5_000_000);
        }
    }

    @Override
    public synchronized int pendingOutput() {
        long left = wireFreeAt - System.nanoTime();
        return left <= 0 ? 0 : (int) Math.ceil(left / nanosPerByte);
    }

    @Override
    public int read(byte[] b) throws IOException {
        return inner.read(b);
    }

    @Override
    public String name() {
        return inner.name() + " (" + Math.round(10e9 / nanosPerByte) + " baud)";
    }

    @Override
    public void close() {
        inner.close();
    }
}
