package org.parpe.serial.servo.host;

import java.io.IOException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.link.LinkCloser;
import org.parpe.serial.link.ReadLoop;
import org.parpe.serial.link.StreamDecoder;
import org.parpe.serial.dynamixel.Dxl2Codec;
import org.parpe.serial.servo.wire.Packet;
import org.parpe.serial.servo.wire.PacketCodec;
import org.parpe.serial.servo.wire.PacketDecoder;

/**
 * Request and reply over one link for a control-table protocol: sends instruction packets and
 * waits for the status packets of the servos named, each kept by servo ID (its first four
 * parameter bytes as a number, its error byte, its length; each servo's block of a Dynamixel Fast
 * Sync Read status is kept as that servo's reply). A reader thread owns the decoder;
 * late replies to an ended request are counted as stray. Requests must come from one thread at a
 * time; plain sends may come from any thread.
 */
final class PacketPort {
    private static final long IDLE_GAP_NANOS = 5_000_000;
    /** The longest Return Delay Time a servo can be set to: 254 × 2 µs (Dynamixel and Feetech alike). */
    private static final long MAX_RETURN_DELAY_NANOS = 508_000;

    private final ByteLink link;
    private final PacketCodec codec;
    private final boolean bigEndian;
    private final int baud;
    private final int timeoutMs;
    private final PacketDecoder rx;
    /** Held packets (from 0), then the packet being sent: what one write puts on the line. */
    private final byte[] out;
    private final byte[] packet;
    private int heldBytes;
    private final Object writeLock = new Object();
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition replied = lock.newCondition();
    private final boolean[] waiting = new boolean[256];
    private final boolean[] got = new boolean[256];
    private final int[] value = new int[256];
    private final int[] error = new int[256];
    private final int[] size = new int[256];
    private final int[] expectedIds = new int[256];
    private final Thread reader;
    private int expected;
    private int waitingCount;
    /** Data bytes per servo of the Fast Sync Read last asked, guarded by lock. */
    private int fastSize;
    // A chain of requests (requestEach), guarded by lock: the reader sends the next as soon as a reply ends one.
    private int[] chainIds;
    private int chainN;
    private int chainAt = -1;
    private int chainInstruction;
    private byte[] chainParams;
    private int chainLen;
    private long chainDeadline;
    private long chainTimeoutNanos;
    private volatile boolean running = true;
    private volatile IOException linkError;
    private volatile long lastWriteNanos;
    /** When the reader last got a byte (at first: when the port opened, so a flush waits a full quiet time). */
    private volatile long lastReadNanos = System.nanoTime();
    private long packetsSent;
    private long timeouts;
    private long stray;

    PacketPort(ByteLink link, PacketCodec codec, boolean bigEndian, int baud, int timeoutMs) {
        this.link = link;
        this.codec = codec;
        this.bigEndian = bigEndian;
        this.baud = baud;
        this.timeoutMs = timeoutMs;
        this.rx = codec.decoder(this::onPacket);
        this.packet = new byte[codec.bufferSize()];
        this.out = new byte[4 * codec.bufferSize()];
        reader = new Thread(this::readLoop, "servo-reader " + link.name());
        reader.setDaemon(true);
        reader.start();
    }

    String name() {
        return link.name();
    }

    /** Sends an instruction packet that gets no reply (after any held ones, in the same write). */
    void send(int id, int instruction, byte[] params, int len) throws IOException {
        synchronized (writeLock) {
            IOException e = linkError;
            if (e != null) {
                heldBytes = 0;
                throw e;
            }
            int n = append(id, instruction, params, len);
            heldBytes = 0;
            link.write(out, 0, n);
            packetsSent++;
            lastWriteNanos = System.nanoTime();
        }
    }

    /**
     * Encodes an instruction packet that gets no reply and keeps it until the next {@link #send}
     * or request, which writes both at once: one system call (and one USB transfer) per cycle
     * instead of two. The caller must send something right after.
     */
    void hold(int id, int instruction, byte[] params, int len) throws IOException {
        synchronized (writeLock) {
            heldBytes = append(id, instruction, params, len);
            packetsSent++;
        }
    }

    /**
     * Encodes a packet after the held ones (writing those first when there is no room), with
     * {@link #writeLock} held; returns the bytes of {@link #out} in use.
     */
    private int append(int id, int instruction, byte[] params, int len) throws IOException {
        if (heldBytes + codec.bufferSize() > out.length) {
            flushHeld();
        }
        int n = codec.instruction(packet, id, instruction, params, len);
        System.arraycopy(packet, 0, out, heldBytes, n);
        return heldBytes + n;
    }

    /** Writes the held packets on their own, with {@link #writeLock} held. */
    private void flushHeld() throws IOException {
        if (heldBytes > 0) {
            int n = heldBytes;
            heldBytes = 0;
            link.write(out, 0, n);
            lastWriteNanos = System.nanoTime();
        }
    }

    /** A request answered by servo {@code replyId}; true when it replied in time. */
    boolean request(int id, int instruction, byte[] params, int len, int replyId) throws IOException {
        lock.lock();
        try {
            expected = 0;
            expect(replyId);
        } finally {
            lock.unlock();
        }
        await(id, instruction, params, len, 1, -1);
        return got[replyId];
    }

    /** A request answered by each of servos {@code replyIds[0…n)} in turn. */
    void requestAll(int id, int instruction, byte[] params, int len, int[] replyIds, int n) throws IOException {
        requestAll(id, instruction, params, len, replyIds, n, -1);
    }

    /**
     * Like {@link #requestAll(int, int, byte[], int, int[], int)}, listening for at most
     * {@code listenNanos} (−1: the read timeout plus every reply's wire time).
     */
    void requestAll(int id, int instruction, byte[] params, int len, int[] replyIds, int n, long listenNanos)
            throws IOException {
        lock.lock();
        try {
            expected = 0;
            for (int i = 0; i < n; i++) {
                expect(replyIds[i]);
            }
        } finally {
            lock.unlock();
        }
        await(id, instruction, params, len, n, listenNanos);
    }

    /**
     * A Dynamixel Fast Sync Read ({@code params}: address, {@code size} and the IDs, as Sync
     * Read) answered by servos {@code replyIds[0…n)} in one status packet from the broadcast ID.
     */
    void requestFast(byte[] params, int len, int size, int[] replyIds, int n) throws IOException {
        lock.lock();
        try {
            fastSize = size;
        } finally {
            lock.unlock();
        }
        requestAll(PacketCodec.BROADCAST, PacketCodec.FAST_SYNC_READ, params, len, replyIds, n, -1);
    }

    /**
     * The same request to each of servos {@code ids[0…n)} in turn, each answered by that servo:
     * the next goes out the moment the reply to the one before has arrived, sent by the reader
     * thread (the caller is not woken between them, which saves a thread switch per servo on buses
     * without Sync Read); a servo that does not reply in time is skipped.
     */
    void requestEach(int instruction, byte[] params, int len, int[] ids, int n) throws IOException {
        if (n == 0) {
            return;
        }
        long perRequest = TimeUnit.MILLISECONDS.toNanos(timeoutMs)
                + (long) (codec.packetLength(len) + codec.packetLength(8)) * 10_000_000_000L / baud
                + MAX_RETURN_DELAY_NANOS;
        lock.lock();
        try {
            expected = 0;
            for (int i = 0; i < n; i++) {
                expect(ids[i]);
            }
            chainIds = ids;
            chainN = n;
            chainInstruction = instruction;
            chainParams = params;
            chainLen = len;
            chainTimeoutNanos = perRequest;
            chainAt = 0;
            chainDeadline = System.nanoTime() + perRequest;
            send(ids[0], instruction, params, len);
            while (chainAt >= 0 && linkError == null) {
                long left = chainDeadline - System.nanoTime();
                if (left <= 0) {
                    // This servo is silent: give up on it and ask the next.
                    waiting[chainIds[chainAt]] = false;
                    waitingCount--;
                    timeouts++;
                    chainNext();
                } else {
                    replied.awaitNanos(left);
                }
            }
        } catch (IOException e) {
            chainAt = -1;
            throw e;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            chainAt = -1;
            lock.unlock();
            forget();
        }
        if (linkError != null) {
            throw linkError;
        }
    }

    /** With {@link #lock} held: the next request of the chain, or its end (the caller is woken). */
    private void chainNext() throws IOException {
        if (++chainAt >= chainN) {
            chainAt = -1;
            replied.signalAll();
            return;
        }
        chainDeadline = System.nanoTime() + chainTimeoutNanos;
        send(chainIds[chainAt], chainInstruction, chainParams, chainLen);
    }

    /** Whether servo {@code id} replied to the last request. */
    boolean got(int id) {
        return got[id];
    }

    /** The first (up to four) parameter bytes of servo {@code id}'s last reply as a number. */
    int value(int id) {
        return value[id];
    }

    /** The error byte of servo {@code id}'s last reply. */
    int error(int id) {
        return error[id];
    }

    /** The parameter count of servo {@code id}'s last reply. */
    int size(int id) {
        return size[id];
    }

    int pendingOutput() {
        return link.pendingOutput();
    }

    IOException linkError() {
        return linkError;
    }

    long packetsSent() {
        synchronized (writeLock) {
            return packetsSent;
        }
    }

    /** Replies that did not come in time, received packets with a bad check, stray replies. */
    long[] receiveCounters() {
        lock.lock();
        try {
            return new long[] {timeouts, rx.checksumErrors(), stray};
        } finally {
            lock.unlock();
        }
    }

    /** Lets what was written reach the far end, then stops the reader and closes the link ({@link LinkCloser#close}). */
    void close() {
        LinkCloser.close(link, () -> linkError != null, () -> lastWriteNanos, () -> running = false, reader);
    }

    /** Adds {@code id} to the replies awaited, with {@link #lock} held. */
    private void expect(int id) {
        expectedIds[expected++] = id;
        waiting[id] = true;
        got[id] = false;
        size[id] = 0;
        waitingCount++;
    }

    private void await(int id, int instruction, byte[] params, int len, int replies, long listenNanos)
            throws IOException {
        try {
            send(id, instruction, params, len);
        } catch (IOException e) {
            forget();
            throw e;
        }
        // Room for every reply on the wire (10 bits a byte) and each servo's longest Return Delay
        // Time on top of the read timeout: servos answer one after the other.
        long wire = replies * ((long) codec.packetLength(8) * 10_000_000_000L / baud + MAX_RETURN_DELAY_NANOS);
        long left = listenNanos >= 0 ? listenNanos : TimeUnit.MILLISECONDS.toNanos(timeoutMs) + wire;
        lock.lock();
        try {
            while (waitingCount > 0 && left > 0 && linkError == null) {
                left = replied.awaitNanos(left);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            lock.unlock();
        }
        forget();
        if (linkError != null) {
            throw linkError;
        }
    }

    /** Ends the current request: replies still missing count as timeouts, late ones as stray. */
    private void forget() {
        lock.lock();
        try {
            timeouts += waitingCount;
            for (int i = 0; i < expected; i++) {
                waiting[expectedIds[i]] = false;
            }
            waitingCount = 0;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Discards what is still arriving from before (the replies of an interrupted run, a servo
     * still answering an earlier request): waits until the line has been quiet for
     * {@code quietMs} (at most {@code maxMs}), then drops any unfinished packet. What was
     * decoded meanwhile nobody waited for, so it counts as stray.
     */
    void flushInput(long quietMs, long maxMs) {
        long quiet = TimeUnit.MILLISECONDS.toNanos(quietMs);
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(maxMs);
        long now;
        while ((now = System.nanoTime()) - lastReadNanos < quiet && now < end && linkError == null) {
            LockSupport.parkNanos(Math.max(100_000, quiet / 4));
        }
        lock.lock();
        try {
            rx.idle();
        } finally {
            lock.unlock();
        }
    }

    private void readLoop() {
        StreamDecoder watched = new StreamDecoder() {
            @Override
            public void feed(byte[] data, int off, int len) {
                lastReadNanos = System.nanoTime();
                rx.feed(data, off, len);
            }

            @Override
            public int pending() {
                return rx.pending();
            }

            @Override
            public void idle() {
                rx.idle();
            }
        };
        ReadLoop.run(link, () -> running, lock, watched, IDLE_GAP_NANOS, 2048, e -> {
            linkError = e;
            replied.signalAll();
        });
    }

    /** On the reader thread with {@link #lock} held. */
    private void onPacket(Packet p) {
        if (codec.marksStatus() && p.code != PacketCodec.STATUS) {
            return;
        }
        if (codec.knows(PacketCodec.FAST_SYNC_READ) && p.id == PacketCodec.BROADCAST) {
            onFastStatus(p);
            return;
        }
        if (!waiting[p.id]) {
            stray++;
            return;
        }
        boolean chained = chainAt >= 0 && chainIds[chainAt] == p.id;
        keep(p.id, p.params, 0, p.length, codec.statusError(p));
        if (chained) {
            try {
                chainNext();
            } catch (IOException e) {
                linkError = e;
                replied.signalAll();
            }
        } else if (waitingCount <= 0) {
            replied.signalAll();
        }
    }

    /**
     * A Fast Sync Read status: each servo's block (error, ID, data; e-Manual, Protocol 2.0, Fast
     * Sync Read) is kept as that servo's reply. On the reader thread with {@link #lock} held.
     */
    private void onFastStatus(Packet p) {
        int n = Dxl2Codec.fastDevices(p.length, fastSize);
        if (n <= 0) {
            stray++;
            return;
        }
        for (int k = 0; k < n; k++) {
            int at = Dxl2Codec.fastIdAt(k, fastSize);
            int id = p.params[at] & 0xFF;
            if (waiting[id]) {
                keep(id, p.params, at + 1, fastSize, k == 0 ? p.error : p.params[at - 1] & 0xFF);
            } else {
                stray++;
            }
        }
        if (waitingCount <= 0) {
            replied.signalAll();
        }
    }

    /** Keeps servo {@code id}'s reply: {@code len} data bytes of {@code params} from {@code off}. */
    private void keep(int id, byte[] params, int off, int len, int statusError) {
        waiting[id] = false;
        got[id] = true;
        int n = Math.min(4, len);
        int v = 0;
        for (int i = 0; i < n; i++) {
            v |= (params[off + i] & 0xFF) << 8 * (bigEndian ? n - 1 - i : i);
        }
        value[id] = v;
        size[id] = len;
        error[id] = statusError;
        --waitingCount;
    }
}
