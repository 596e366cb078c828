package org.parpe.serial.g1;

import java.io.IOException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.link.LinkCloser;
import org.parpe.serial.link.ReadLoop;

/**
 * The host end of one open link: sends frames and runs request/reply transactions with a timeout
 * and retries. A reader thread owns the decoder; a reply is matched by address and command, and
 * late replies to an abandoned request are counted and ignored. Transactions must come from one
 * thread at a time; plain frames (setpoints, emergency stop) may be sent from any thread.
 */
public final class BusMaster implements AutoCloseable {
    private final ByteLink link;
    private final BusConfig config;
    private final FrameEncoder tx = new FrameEncoder();
    private final FrameDecoder rx = new FrameDecoder(this::onFrame);
    private final Object writeLock = new Object();
    private final ReentrantLock replyLock = new ReentrantLock();
    private final Condition replied = replyLock.newCondition();
    private final Reply incoming = new Reply();
    private final Thread reader;
    private volatile boolean running = true;
    private volatile IOException linkError;
    private volatile long lastReplyNanos = System.nanoTime();
    private volatile long lastWriteNanos;
    private int expectAddr = -1;
    private int expectCmd = -1;
    private boolean ready;
    private long framesSent;
    private long timeouts;
    private long retried;
    private long failures;
    private long stray;

    /** Starts talking over {@code link}. */
    public BusMaster(ByteLink link, BusConfig config) {
        this.link = link;
        this.config = config;
        reader = new Thread(this::readLoop, "bus-reader " + link.name());
        reader.setDaemon(true);
        reader.start();
    }

    /** The link's name (device path). */
    public String name() {
        return link.name();
    }

    /** Bytes still queued for the wire. */
    public int pendingOutput() {
        return link.pendingOutput();
    }

    /** The error that ended the link, or null while it works. */
    public IOException linkError() {
        return linkError;
    }

    /** {@link System#nanoTime()} of the last valid reply (or of the start). */
    public long lastReplyNanos() {
        return lastReplyNanos;
    }

    /** Sends a frame without payload. */
    public void send(int addr, Command cmd) throws IOException {
        synchronized (writeLock) {
            write(tx.simple(addr, cmd));
        }
    }

    /** Sends HOLD to {@code addr}: at the current angle, or finishing the move to the last setpoint. */
    public void sendHold(int addr, boolean keepTarget) throws IOException {
        synchronized (writeLock) {
            write(tx.begin(addr, Command.HOLD).putU8(keepTarget ? Protocol.HOLD_TARGET : 0).finish());
        }
    }

    /** Broadcasts setpoints for modules {@code first … first+count−1} (wire units). */
    public void sendSetpoints(int seq, int first, short[] wire, int count) throws IOException {
        synchronized (writeLock) {
            write(tx.setpoints(seq, first, wire, count));
        }
    }

    /** Broadcasts the watchdog time, safe mode and speed limit (0 keeps the modules' own). */
    public void sendConfig(int watchdogMs, SafeMode mode, int speedDegPerS) throws IOException {
        synchronized (writeLock) {
            write(tx.begin(Protocol.BROADCAST, Command.CONFIG).putU16(watchdogMs).putU8(mode.wire())
                    .putU16(speedDegPerS).finish());
        }
    }

    /** Broadcasts an emergency stop, latched by every module until RESUME. */
    public void sendEmergencyStop(SafeMode mode) throws IOException {
        synchronized (writeLock) {
            write(tx.begin(Protocol.BROADCAST, Command.ESTOP).putU8(mode.wire()).finish());
        }
    }

    /**
     * Pings module {@code id} with up to {@code attempts} tries; on success {@code out} holds its
     * angle and flags.
     */
    public boolean ping(int id, Reply out, int attempts) throws IOException {
        return transact(id, Command.PING, Command.PONG, out, attempts);
    }

    /** Reads module {@code id}'s sensors with the configured retries. */
    public boolean read(int id, Reply out) throws IOException {
        return read(id, out, config.retries() + 1);
    }

    /** Reads module {@code id}'s sensors with up to {@code attempts} tries. */
    public boolean read(int id, Reply out, int attempts) throws IOException {
        return transact(id, Command.READ, Command.STATUS, out, attempts);
    }

    /**
     * Counters.
     *
     * @param framesSent     frames written
     * @param timeouts       requests that got no reply in time
     * @param retried        transactions that succeeded after a timeout
     * @param failures       transactions that failed on every attempt
     * @param checksumErrors received frames with a bad CRC
     * @param stray          valid frames nobody waited for (late replies)
     */
    public record Counters(long framesSent, long timeouts, long retried, long failures, long checksumErrors,
                           long stray) {
    }

    /** A snapshot of the counters. */
    public Counters counters() {
        long sent;
        synchronized (writeLock) {
            sent = framesSent;
        }
        replyLock.lock();
        try {
            return new Counters(sent, timeouts, retried, failures, rx.checksumErrors(), stray);
        } finally {
            replyLock.unlock();
        }
    }

    /**
     * Waits up to {@code timeoutMs} until every byte written has left the output queue; closing a
     * port may discard what is still queued (the final HOLD, for instance).
     */
    public void drain(long timeoutMs) {
        LinkCloser.drain(link, () -> linkError != null, timeoutMs);
    }

    /** Lets what was written reach the far end, then stops the reader and closes the link ({@link LinkCloser#close}). */
    @Override
    public void close() {
        LinkCloser.close(link, () -> linkError != null, () -> lastWriteNanos, () -> running = false, reader);
    }

    private boolean transact(int id, Command cmd, Command replyCmd, Reply out, int attempts) throws IOException {
        for (int attempt = 0; attempt < attempts; attempt++) {
            replyLock.lock();
            try {
                expectAddr = id;
                expectCmd = replyCmd.code();
                ready = false;
            } finally {
                replyLock.unlock();
            }
            send(id, cmd);
            if (awaitReply(out)) {
                if (attempt > 0) {
                    count(1);
                }
                return true;
            }
            count(0);
        }
        count(2);
        return false;
    }

    private boolean awaitReply(Reply out) throws IOException {
        long left = TimeUnit.MILLISECONDS.toNanos(config.readTimeoutMs());
        replyLock.lock();
        try {
            while (!ready && left > 0 && linkError == null) {
                left = replied.awaitNanos(left);
            }
            expectAddr = -1;
            if (ready) {
                out.copyFrom(incoming);
                return true;
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            replyLock.unlock();
        }
        if (linkError != null) {
            throw linkError;
        }
        return false;
    }

    private void count(int what) {
        replyLock.lock();
        try {
            switch (what) {
                case 0 -> timeouts++;
                case 1 -> retried++;
                default -> failures++;
            }
        } finally {
            replyLock.unlock();
        }
    }

    private void write(int n) throws IOException {
        IOException e = linkError;
        if (e != null) {
            throw e;
        }
        link.write(tx.buffer(), 0, n);
        framesSent++;
        lastWriteNanos = System.nanoTime();
    }

    private void readLoop() {
        ReadLoop.run(link, () -> running, replyLock, rx, TimeUnit.MILLISECONDS.toNanos(config.idleGapMs()), 1024, e -> {
            linkError = e;
            replied.signalAll();
        });
    }

    /** Called by the decoder on the reader thread, with {@link #replyLock} held. */
    private void onFrame(int addr, int cmd, byte[] buf, int off, int len) {
        if (addr == expectAddr && cmd == expectCmd && !ready && incoming.decode(cmd, buf, off, len)) {
            ready = true;
            lastReplyNanos = System.nanoTime();
            replied.signalAll();
        } else if (Command.replies(cmd)) {
            // A late reply still shows that the bus is alive.
            lastReplyNanos = System.nanoTime();
            stray++;
        }
    }
}
