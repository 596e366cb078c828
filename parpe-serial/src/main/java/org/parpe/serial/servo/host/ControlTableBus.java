package org.parpe.serial.servo.host;

import java.io.IOException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.servo.Registers;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.wire.Dxl2Codec;
import org.parpe.serial.servo.wire.FeetechCodec;
import org.parpe.serial.servo.wire.Packet;
import org.parpe.serial.servo.wire.PacketCodec;
import org.parpe.serial.servo.wire.PacketDecoder;

/**
 * The host end of a control-table servo bus (Dynamixel Protocol 2.0, Feetech STS or SCS). Goals
 * and torque go out as one Sync Write per register layout; positions come back by Sync Read
 * (Dynamixel, STS), Bulk Read (Dynamixel servos with different layouts on one bus) or one Read
 * per servo (SCS, which has no Sync Read). A reader thread owns the decoder and hands replies to
 * the waiting request by servo ID.
 */
public final class ControlTableBus implements ServoBus {
    private static final long LINGER_MS = 50;
    /** Bus Watchdog after it tripped: −1 in one byte. */
    private static final int WATCHDOG_TRIPPED = 0xFF;

    private final ServoProtocol protocol;
    private final ByteLink link;
    private final int baud;
    private final int timeoutMs;
    private final PacketCodec codec;
    private final boolean bigEndian;
    private final PacketDecoder rx;
    private final byte[] out;
    private final byte[] params = new byte[Packet.MAX_PARAMS];
    private final Object writeLock = new Object();
    private final ReentrantLock replyLock = new ReentrantLock();
    private final Condition replied = replyLock.newCondition();
    private final boolean[] waiting = new boolean[256];
    private final int[] value = new int[256];
    private final int[] error = new int[256];
    private final int[] answerSize = new int[256];
    private final boolean[] got = new boolean[256];
    private final int[] expectedIds = new int[256];
    private int expected;
    private final Thread reader;
    private int waitingCount;
    private volatile boolean running = true;
    private volatile IOException linkError;
    private volatile long lastWriteNanos;
    private long packetsSent;
    private long timeouts;
    private long stray;

    /** Starts talking {@code protocol} (not G1) over {@code link} running at {@code baud}. */
    public ControlTableBus(ServoProtocol protocol, ByteLink link, int baud, int timeoutMs) {
        if (protocol == ServoProtocol.G1) {
            throw new IllegalArgumentException("G1 is not a control-table protocol; use G1Bus");
        }
        this.protocol = protocol;
        this.link = link;
        this.baud = baud;
        this.timeoutMs = timeoutMs;
        this.codec = protocol == ServoProtocol.DXL2 ? new Dxl2Codec() : new FeetechCodec(protocol == ServoProtocol.SCS);
        this.bigEndian = protocol == ServoProtocol.SCS;
        this.out = new byte[codec.bufferSize()];
        this.rx = codec.decoder(this::onPacket);
        reader = new Thread(this::readLoop, "servo-reader " + link.name());
        reader.setDaemon(true);
        reader.start();
    }

    @Override
    public ServoProtocol protocol() {
        return protocol;
    }

    @Override
    public String name() {
        return link.name();
    }

    @Override
    public int ping(int id, int attempts) throws IOException {
        for (int a = 0; a < attempts; a++) {
            if (transact(id, PacketCodec.PING, 0, id)) {
                if (protocol == ServoProtocol.DXL2) {
                    // The status of a Dynamixel ping carries the model number (2 bytes) and firmware version.
                    return answerSize[id] >= 3 ? value[id] & 0xFFFF : 0;
                }
                int model = read(id, Registers.FEETECH.model(), 2, attempts - a);
                return model == Integer.MIN_VALUE ? 0 : model;
            }
        }
        return -1;
    }

    /**
     * On Dynamixel 2.0 a broadcast Ping, which every servo answers in turn (twice, merging the
     * answers); Feetech servos are pinged one by one.
     */
    @Override
    public int[] scan(int[] ids) throws IOException {
        if (protocol != ServoProtocol.DXL2) {
            return ServoBus.super.scan(ids);
        }
        int[] models = new int[ids.length];
        java.util.Arrays.fill(models, -1);
        ServoModel[] any = new ServoModel[ids.length];
        java.util.Arrays.fill(any, ServoModel.defaultFor(protocol));
        for (int pass = 0; pass < 2; pass++) {
            transact(PacketCodec.BROADCAST, PacketCodec.PING, 0, ids, any, ids.length, null);
            replyLock.lock();
            try {
                for (int i = 0; i < ids.length; i++) {
                    if (got[ids[i]] && models[i] < 0) {
                        models[i] = answerSize[ids[i]] >= 3 ? value[ids[i]] & 0xFFFF : 0;
                    }
                }
            } finally {
                replyLock.unlock();
            }
        }
        return models;
    }

    /** Reads {@code size} bytes at {@code addr} of servo {@code id}: the value, or {@link Integer#MIN_VALUE}. */
    public int read(int id, int addr, int size, int attempts) throws IOException {
        for (int a = 0; a < attempts; a++) {
            int n = putAddress(0, addr, size);
            if (transact(id, PacketCodec.READ, n, id) && answerSize[id] >= size) {
                return value[id];
            }
        }
        return Integer.MIN_VALUE;
    }

    /** Writes {@code value} ({@code size} bytes) at {@code addr} of servo {@code id}; true when it acknowledged. */
    public boolean write(int id, int addr, int size, int v) throws IOException {
        int n = putAddress(0, addr, -1);
        n = put(n, v, size);
        return transact(id, PacketCodec.WRITE, n, id) && error[id] == 0;
    }

    @Override
    public void torque(int[] ids, ServoModel[] models, int n, boolean on) throws IOException {
        for (Registers r : layouts(models, n)) {
            syncWrite(r.torque(), 1, ids, models, null, on ? 1 : 0, n, r);
        }
    }

    @Override
    public void writeGoals(int[] ids, ServoModel[] models, int[] ticks, int n) throws IOException {
        for (Registers r : layouts(models, n)) {
            syncWrite(r.goal(), r.goalSize(), ids, models, ticks, 0, n, r);
        }
    }

    @Override
    public int readPositions(int[] ids, ServoModel[] models, int n, double[] degrees, int[] errors) throws IOException {
        java.util.List<Registers> layouts = layouts(models, n);
        if (protocol == ServoProtocol.SCS) {
            for (int i = 0; i < n; i++) {
                Registers r = models[i].registers();
                int k = putAddress(0, r.present(), r.presentSize());
                transact(ids[i], PacketCodec.READ, k, ids[i]);
            }
        } else if (layouts.size() == 1 || protocol != ServoProtocol.DXL2) {
            for (Registers r : layouts) {
                int k = putAddress(0, r.present(), r.presentSize());
                for (int i = 0; i < n; i++) {
                    if (models[i].registers() == r) {
                        params[k++] = (byte) ids[i];
                    }
                }
                transact(PacketCodec.BROADCAST, PacketCodec.SYNC_READ, k, ids, models, n, r);
            }
        } else {
            int k = 0;
            for (int i = 0; i < n; i++) {
                Registers r = models[i].registers();
                params[k++] = (byte) ids[i];
                k = putAddress(k, r.present(), r.presentSize());
            }
            transact(PacketCodec.BROADCAST, PacketCodec.BULK_READ, k, ids, models, n, null);
        }
        int answered = 0;
        replyLock.lock();
        try {
            for (int i = 0; i < n; i++) {
                int id = ids[i];
                int size = models[i].registers().presentSize();
                if (!got[id] || answerSize[id] < size) {
                    errors[i] = NO_REPLY;
                } else {
                    degrees[i] = models[i].degrees(value[id], size);
                    errors[i] = error[id];
                    answered++;
                }
            }
        } finally {
            replyLock.unlock();
        }
        return answered;
    }

    @Override
    public boolean faulty(int statusError) {
        if (statusError <= 0) {
            return false;
        }
        return protocol != ServoProtocol.DXL2 || Faults.alert(statusError);
    }

    @Override
    public String describeFault(int id, ServoModel model, int statusError) throws IOException {
        int bits = read(id, model.registers().error(), 1, 2);
        return bits == Integer.MIN_VALUE ? null : Faults.describe(protocol, statusError, bits);
    }

    @Override
    public String watchdog(int[] ids, ServoModel[] models, int n, int ms, boolean limp) throws IOException {
        if (protocol != ServoProtocol.DXL2) {
            return "Feetech servos have no watchdog: they hold their last goal when the host falls silent";
        }
        // Units of 20 ms; writing 0 first also clears an earlier Bus Watchdog error.
        int units = watchdogUnits(ms);
        int covered = 0;
        for (int i = 0; i < n; i++) {
            int addr = models[i].registers().watchdog();
            if (addr >= 0 && write(ids[i], addr, 1, 0) && (units == 0 || write(ids[i], addr, 1, units))) {
                covered++;
            }
        }
        return covered + " of " + n + " servos stop and hold after " + units * 20 + " ms without a packet (Bus Watchdog)"
                + (limp ? "; Dynamixel servos cannot go limp on their own, PARPE turns their torque off when it can" : "");
    }

    @Override
    public boolean resumeIfTripped(int id, ServoModel model, int statusError, int ms) throws IOException {
        int addr = model.registers().watchdog();
        if (addr < 0 || ms <= 0 || read(id, addr, 1, 1) != WATCHDOG_TRIPPED) {
            return false;
        }
        return write(id, addr, 1, 0) && write(id, addr, 1, watchdogUnits(ms));
    }

    @Override
    public void emergencyStop(int[] ids, ServoModel[] models, int n, boolean limp) throws IOException {
        if (limp) {
            for (int pass = 0; pass < 3; pass++) {
                torque(ids, models, n, false);
            }
            return;
        }
        holdHere(ids, models, n);
    }

    @Override
    public int pendingOutput() {
        return link.pendingOutput();
    }

    @Override
    public Counters counters() {
        replyLock.lock();
        try {
            synchronized (writeLock) {
                return new Counters(packetsSent, timeouts, rx.checksumErrors(), stray);
            }
        } finally {
            replyLock.unlock();
        }
    }

    @Override
    public IOException linkError() {
        return linkError;
    }

    @Override
    public void close() {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(250);
        while (linkError == null && link.pendingOutput() > 0 && System.nanoTime() < deadline) {
            java.util.concurrent.locks.LockSupport.parkNanos(200_000);
        }
        long linger = lastWriteNanos + TimeUnit.MILLISECONDS.toNanos(LINGER_MS) - System.nanoTime();
        if (linger > 0 && linkError == null) {
            java.util.concurrent.locks.LockSupport.parkNanos(linger);
        }
        running = false;
        link.close();
        try {
            reader.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Bus Watchdog units (20 ms) of {@code ms}, 0 for off. */
    private static int watchdogUnits(int ms) {
        return ms <= 0 ? 0 : Math.max(1, Math.min(127, (ms + 19) / 20));
    }

    /** The distinct register layouts of models {@code 0…n)}, in order of first use. */
    private static java.util.List<Registers> layouts(ServoModel[] models, int n) {
        java.util.List<Registers> l = new java.util.ArrayList<>(2);
        for (int i = 0; i < n; i++) {
            if (!l.contains(models[i].registers())) {
                l.add(models[i].registers());
            }
        }
        return l;
    }

    /** One Sync Write of {@code size} bytes at {@code addr} to the servos of layout {@code r}. */
    private void syncWrite(int addr, int size, int[] ids, ServoModel[] models, int[] values, int constant, int n,
                           Registers r) throws IOException {
        synchronized (writeLock) {
            int k = putAddress(0, addr, size);
            for (int i = 0; i < n; i++) {
                if (models[i].registers() == r) {
                    params[k++] = (byte) ids[i];
                    k = put(k, values == null ? constant : values[i], size);
                }
            }
            send(PacketCodec.BROADCAST, PacketCodec.SYNC_WRITE, k);
        }
    }

    /** Address (and length unless {@code size} < 0) as the protocol encodes them, from {@code k}. */
    private int putAddress(int k, int addr, int size) {
        if (protocol == ServoProtocol.DXL2) {
            PacketCodec.putLe(params, k, 2, addr);
            k += 2;
            if (size >= 0) {
                PacketCodec.putLe(params, k, 2, size);
                k += 2;
            }
            return k;
        }
        params[k++] = (byte) addr;
        if (size >= 0) {
            params[k++] = (byte) size;
        }
        return k;
    }

    private int put(int k, int v, int size) {
        for (int i = 0; i < size; i++) {
            params[k + i] = (byte) (v >>> 8 * (bigEndian ? size - 1 - i : i));
        }
        return k + size;
    }

    private void send(int id, int instruction, int paramLen) throws IOException {
        synchronized (writeLock) {
            IOException e = linkError;
            if (e != null) {
                throw e;
            }
            int len = codec.instruction(out, id, instruction, params, paramLen);
            link.write(out, 0, len);
            packetsSent++;
            lastWriteNanos = System.nanoTime();
        }
    }

    /** A request to one servo; true when it replied in time. */
    private boolean transact(int id, int instruction, int paramLen, int replyId) throws IOException {
        replyLock.lock();
        try {
            expected = 0;
            expect(replyId);
        } finally {
            replyLock.unlock();
        }
        await(id, instruction, paramLen, 1);
        return got[replyId];
    }

    /** A request answered by every servo of layout {@code r} (all when null) among {@code 0…n)}. */
    private void transact(int id, int instruction, int paramLen, int[] ids, ServoModel[] models, int n, Registers r)
            throws IOException {
        replyLock.lock();
        try {
            expected = 0;
            for (int i = 0; i < n; i++) {
                if (r == null || models[i].registers() == r) {
                    expect(ids[i]);
                }
            }
        } finally {
            replyLock.unlock();
        }
        await(id, instruction, paramLen, expected);
    }

    /** Adds {@code id} to the replies awaited, with {@link #replyLock} held. */
    private void expect(int id) {
        expectedIds[expected++] = id;
        waiting[id] = true;
        got[id] = false;
        answerSize[id] = 0;
        waitingCount++;
    }

    /** Sends and waits for the {@code replies} expected replies; the replies are in {@link #got} and its arrays. */
    private void await(int id, int instruction, int paramLen, int replies) throws IOException {
        try {
            send(id, instruction, paramLen);
        } catch (IOException e) {
            forget();
            throw e;
        }
        // Room for every reply on the wire (10 bits a byte) on top of the read timeout.
        long wire = (long) replies * codec.packetLength(8) * 10_000_000_000L / baud;
        long left = TimeUnit.MILLISECONDS.toNanos(timeoutMs) + wire;
        replyLock.lock();
        try {
            while (waitingCount > 0 && left > 0 && linkError == null) {
                left = replied.awaitNanos(left);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            replyLock.unlock();
        }
        forget();
        if (linkError != null) {
            throw linkError;
        }
    }

    /** Ends the current request: late replies count as stray. */
    private void forget() {
        replyLock.lock();
        try {
            timeouts += waitingCount;
            for (int i = 0; i < expected; i++) {
                waiting[expectedIds[i]] = false;
            }
            waitingCount = 0;
        } finally {
            replyLock.unlock();
        }
    }

    private void readLoop() {
        byte[] in = new byte[2048];
        long lastByte = System.nanoTime();
        while (running) {
            int n;
            try {
                n = link.read(in);
            } catch (IOException e) {
                replyLock.lock();
                try {
                    linkError = e;
                    replied.signalAll();
                } finally {
                    replyLock.unlock();
                }
                return;
            }
            long now = System.nanoTime();
            replyLock.lock();
            try {
                if (n > 0) {
                    lastByte = now;
                    rx.feed(in, 0, n);
                } else if (rx.pending() > 0 && now - lastByte > 5_000_000L) {
                    rx.idle();
                }
            } finally {
                replyLock.unlock();
            }
        }
    }

    /** On the reader thread with {@link #replyLock} held. */
    private void onPacket(Packet p) {
        if (protocol == ServoProtocol.DXL2 && p.code != PacketCodec.STATUS) {
            return;
        }
        if (!waiting[p.id]) {
            stray++;
            return;
        }
        waiting[p.id] = false;
        got[p.id] = true;
        int size = Math.min(4, p.length);
        int v = 0;
        for (int i = 0; i < size; i++) {
            v |= (p.params[i] & 0xFF) << 8 * (bigEndian ? size - 1 - i : i);
        }
        value[p.id] = v;
        answerSize[p.id] = p.length;
        error[p.id] = codec.statusError(p);
        if (--waitingCount <= 0) {
            replied.signalAll();
        }
    }
}
