package org.parpe.serial.link;

import org.parpe.serial.text.SerialMsg;
import java.io.IOException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * An in-memory link: {@link #pair} gives two ends where what one writes the other reads, like a
 * null-modem cable. Used by tests and benchmarks that do not need a real device.
 */
public final class PipeLink implements ByteLink {
    private final Buffer in;
    private final Buffer out;
    private final String name;

    private PipeLink(Buffer in, Buffer out, String name) {
        this.in = in;
        this.out = out;
        this.name = name;
    }

    /** Two connected ends, called {@code name-a} and {@code name-b}. */
    public static PipeLink[] pair(String name) {
        Buffer ab = new Buffer();
        Buffer ba = new Buffer();
        return new PipeLink[] {new PipeLink(ba, ab, name + "-a"), new PipeLink(ab, ba, name + "-b")};
    }

    @Override
    public void write(byte[] b, int off, int len) throws IOException {
        out.put(b, off, len, name);
    }

    @Override
    public int read(byte[] b) throws IOException {
        return in.take(b, name);
    }

    @Override
    public String name() {
        return name;
    }

    /** Closes both directions, as pulling the cable would. */
    @Override
    public void close() {
        in.close();
        out.close();
    }

    /** A bounded ring buffer for one direction. */
    private static final class Buffer {
        private final byte[] ring = new byte[1 << 16];
        private final ReentrantLock lock = new ReentrantLock();
        private final Condition changed = lock.newCondition();
        private int head;
        private int size;
        private boolean closed;

        void put(byte[] b, int off, int len, String name) throws IOException {
            lock.lock();
            try {
                while (len > 0) {
                    if (closed) {
                        throw new LinkException(SerialMsg.LINK_CLOSED.text(name));
                    }
                    if (size == ring.length) {
                        changed.awaitNanos(1_000_000);
                        continue;
                    }
                    int tail = (head + size) % ring.length;
                    int n = Math.min(len, Math.min(ring.length - size, ring.length - tail));
                    System.arraycopy(b, off, ring, tail, n);
                    size += n;
                    off += n;
                    len -= n;
                    changed.signalAll();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new LinkException(name + ": interrupted");
            } finally {
                lock.unlock();
            }
        }

        int take(byte[] b, String name) throws IOException {
            lock.lock();
            try {
                if (size == 0 && !closed) {
                    changed.await(1, TimeUnit.MILLISECONDS);
                }
                if (closed) {
                    throw new LinkException(SerialMsg.LINK_CLOSED.text(name));
                }
                int n = Math.min(b.length, Math.min(size, ring.length - head));
                System.arraycopy(ring, head, b, 0, n);
                head = (head + n) % ring.length;
                size -= n;
                changed.signalAll();
                return n;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new LinkException(name + ": interrupted");
            } finally {
                lock.unlock();
            }
        }

        void close() {
            lock.lock();
            try {
                closed = true;
                changed.signalAll();
            } finally {
                lock.unlock();
            }
        }
    }
}
