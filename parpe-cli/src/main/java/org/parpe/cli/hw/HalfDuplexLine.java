package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
import java.io.IOException;
import java.util.ArrayDeque;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.link.LinkException;

/**
 * An in-memory half-duplex servo line at a given baud rate, for the benchmark: one wire shared by
 * both directions, each byte taking ten bit times (start, 8 data, stop). A write returns at once,
 * like a UART's kernel queue; its bytes reach the other end when the last of them has crossed
 * the wire, after whatever was already on it (requests and replies never overlap, as on a real
 * servo bus). The reading end spins for the last tenth of a millisecond so that delivery is on
 * time, not late by a thread's wake-up.
 *
 * <p>Simulated: the line time of every byte in both directions and the serialisation of the
 * two directions. Not simulated: a USB adapter's latency (an FTDI at 1 ms latency timer adds up
 * to 1 ms per reply), the servos' Return Delay Time (Dynamixel default 500 µs; set it to 0 for
 * fast buses) and their processing time (tens of µs in real servos, the emulator's own here).
 */
final class HalfDuplexLine {
    private static final long SPIN_NANOS = 100_000;

    private final ReentrantLock lock = new ReentrantLock();
    private final double nanosPerByte;
    private long lineFreeAt;
    private long bytes;
    private final End a;
    private final End b;

    private HalfDuplexLine(int baud, String name) {
        this.nanosPerByte = 10e9 / baud;
        Condition toA = lock.newCondition();
        Condition toB = lock.newCondition();
        ArrayDeque<Chunk> qa = new ArrayDeque<>();
        ArrayDeque<Chunk> qb = new ArrayDeque<>();
        a = new End(name + "-a", qa, toA, qb, toB);
        b = new End(name + "-b", qb, toB, qa, toA);
    }

    /** A line at {@code baud}; {@link #host()} and {@link #servos()} are its two ends. */
    static HalfDuplexLine open(int baud, String name) {
        return new HalfDuplexLine(baud, name);
    }

    ByteLink host() {
        return a;
    }

    ByteLink servos() {
        return b;
    }

    /** Bytes that have been put on the wire in either direction so far. */
    long bytes() {
        lock.lock();
        try {
            return bytes;
        } finally {
            lock.unlock();
        }
    }

    /** Bytes and the time their last one arrives at the far end. */
    private record Chunk(byte[] data, long arrives) {
    }

    private final class End implements ByteLink {
        private final String name;
        private final ArrayDeque<Chunk> in;
        private final Condition arrived;
        private final ArrayDeque<Chunk> out;
        private final Condition sent;
        private Chunk partial;
        private int partialOff;
        private long lastArrival;
        private boolean closed;

        End(String name, ArrayDeque<Chunk> in, Condition arrived, ArrayDeque<Chunk> out, Condition sent) {
            this.name = name;
            this.in = in;
            this.arrived = arrived;
            this.out = out;
            this.sent = sent;
        }

        @Override
        public void write(byte[] data, int off, int len) throws IOException {
            lock.lock();
            try {
                if (closed) {
                    throw new LinkException(CliMsg.LINE_CLOSED.text(name));
                }
                long now = System.nanoTime();
                lineFreeAt = Math.max(now, lineFreeAt) + (long) (len * nanosPerByte);
                lastArrival = lineFreeAt;
                bytes += len;
                byte[] copy = new byte[len];
                System.arraycopy(data, off, copy, 0, len);
                out.add(new Chunk(copy, lineFreeAt));
                sent.signalAll();
            } finally {
                lock.unlock();
            }
        }

        @Override
        public int read(byte[] into) throws IOException {
            Chunk c;
            lock.lock();
            try {
                if (partial == null && in.isEmpty() && !closed) {
                    arrived.await(1, TimeUnit.MILLISECONDS);
                }
                if (closed) {
                    throw new LinkException(CliMsg.LINE_CLOSED.text(name));
                }
                if (partial == null && in.isEmpty()) {
                    return 0;
                }
                c = partial != null ? partial : in.peek();
                long early = c.arrives() - System.nanoTime() - SPIN_NANOS;
                if (early > 0) {
                    arrived.awaitNanos(early);
                    return 0; // the caller reads again; closing wakes it sooner
                }
                if (partial == null) {
                    in.poll();
                    partial = c;
                    partialOff = 0;
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new LinkException(name + ": interrupted");
            } finally {
                lock.unlock();
            }
            while (System.nanoTime() - c.arrives() < 0) {
                Thread.onSpinWait();
            }
            int n = Math.min(into.length, c.data().length - partialOff);
            System.arraycopy(c.data(), partialOff, into, 0, n);
            partialOff += n;
            if (partialOff == c.data().length) {
                partial = null;
            }
            return n;
        }

        @Override
        public int pendingOutput() {
            lock.lock();
            try {
                long left = lastArrival - System.nanoTime();
                return left <= 0 ? 0 : (int) Math.ceil(left / nanosPerByte);
            } finally {
                lock.unlock();
            }
        }

        @Override
        public String name() {
            return name;
        }

        @Override
        public void close() {
            lock.lock();
            try {
                a.closed = true;
                b.closed = true;
                a.arrived.signalAll();
                b.arrived.signalAll();
            } finally {
                lock.unlock();
            }
        }
    }
}
