package org.parpe.serial.emu;

import java.io.IOException;
import java.util.Arrays;
import java.util.Random;
import java.util.concurrent.locks.LockSupport;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.protocol.FrameDecoder;
import org.parpe.serial.protocol.FrameEncoder;
import org.parpe.serial.protocol.FrameHandler;
import org.parpe.serial.protocol.Protocol;

/**
 * Emulates a chain of modules on the far end of a serial link, byte for byte as the protocol
 * says. Incoming bytes pass a perfect decoder, then the fault injector (which drops a frame or
 * changes one of its bytes), then the modules' own decoder, so corrupted frames are really
 * rejected by their CRC. A physics thread moves the servos at their speed limit every 2 ms and
 * trips each module's watchdog when no frame arrived for the configured time. If the device
 * goes away, the emulator keeps reopening it.
 */
public final class BusEmulator implements AutoCloseable {
    private static final long PHYSICS_NANOS = 2_000_000;
    private static final long IDLE_GAP_NANOS = 20_000_000;
    private static final long REOPEN_NANOS = 100_000_000;

    /**
     * Counters of one emulator.
     *
     * @param frames         frames the modules accepted
     * @param dropped        frames lost on purpose, both directions
     * @param corrupted      frames given a wrong byte on purpose, both directions
     * @param checksumErrors frames the modules rejected by CRC
     * @param replies        replies sent
     */
    public record Stats(long frames, long dropped, long corrupted, long checksumErrors, long replies) {
    }

    private final LinkOpener opener;
    private final EmulatorOptions options;
    private final EmulatorListener listener;
    private final ServoModule[] modules;
    private final ServoModule[] byId = new ServoModule[256];
    private final double[] view;
    private final FrameDecoder wire = new FrameDecoder(this::onWireFrame);
    private final FrameDecoder moduleRx = new FrameDecoder(this::onModuleFrame);
    private final FrameEncoder tx = new FrameEncoder();
    private final byte[] scratch = new byte[Protocol.MAX_FRAME];
    private final Random random;
    private final Object lock = new Object();
    private final long startNanos = System.nanoTime();
    private final Thread rxThread;
    private final Thread physicsThread;
    private volatile boolean running = true;
    private volatile long lastFrameNanos = System.nanoTime();
    private volatile long lastPollNanos = System.nanoTime();
    private volatile boolean deviceGone;
    private ByteLink link;
    private boolean unplugged;
    private int watchdogMs = 50;
    private int safeMode = Protocol.SAFE_HOLD;
    private double speed;
    private long frames;
    private long dropped;
    private long corrupted;
    private long replies;

    private BusEmulator(LinkOpener opener, ByteLink first, EmulatorOptions options, EmulatorListener listener) {
        this.opener = opener;
        this.link = first;
        this.options = options;
        this.listener = listener;
        this.speed = options.speedDegPerS();
        this.random = new Random(options.seed());
        int[] ids = options.modules().clone();
        Arrays.sort(ids);
        modules = new ServoModule[ids.length];
        for (int i = 0; i < ids.length; i++) {
            modules[i] = new ServoModule(ids[i]);
            byId[ids[i]] = modules[i];
        }
        view = new double[ids.length];
        rxThread = new Thread(this::rxLoop, "emulator-rx " + first.name());
        physicsThread = new Thread(this::physicsLoop, "emulator-physics");
        rxThread.setDaemon(true);
        physicsThread.setDaemon(true);
    }

    /** Opens the device through {@code opener} (errors surface here) and starts serving it. */
    public static BusEmulator start(LinkOpener opener, EmulatorOptions options, EmulatorListener listener)
            throws IOException {
        BusEmulator e = new BusEmulator(opener, opener.open(), options, listener);
        e.rxThread.start();
        e.physicsThread.start();
        return e;
    }

    /** The emulated module IDs, ascending. */
    public int[] moduleIds() {
        return Arrays.stream(modules).mapToInt(m -> m.id).toArray();
    }

    /** The servo angle of module {@code id}, degrees. */
    public double angle(int id) {
        synchronized (lock) {
            return module(id).angle;
        }
    }

    /** Whether module {@code id} is limp (servo off). */
    public boolean isLimp(int id) {
        synchronized (lock) {
            return module(id).limp;
        }
    }

    /** Whether module {@code id} stopped on its watchdog or an emergency stop. */
    public boolean isSafeStopped(int id) {
        synchronized (lock) {
            ServoModule m = module(id);
            return m.watchdogTripped || m.estop;
        }
    }

    /** Moves a limp module by hand (posing); returns false, and does nothing, if it is driven. */
    public boolean backDrive(int id, double degrees) {
        synchronized (lock) {
            ServoModule m = module(id);
            if (!m.limp) {
                return false;
            }
            m.angle = Math.max(-Protocol.JOINT_LIMIT_DEG, Math.min(Protocol.JOINT_LIMIT_DEG, degrees));
            m.target = m.angle;
            return true;
        }
    }

    /** Sets the touch bits of module {@code id} ({@link Protocol#TOUCH_LEFT}, {@link Protocol#TOUCH_RIGHT}). */
    public void setTouch(int id, int bits) {
        synchronized (lock) {
            module(id).touch = bits;
        }
    }

    /** The counters so far. */
    public Stats stats() {
        synchronized (lock) {
            return new Stats(frames, dropped, corrupted, moduleRx.checksumErrors(), replies);
        }
    }

    /** Stops serving and closes the device. */
    @Override
    public void close() {
        running = false;
        rxThread.interrupt();
        physicsThread.interrupt();
        try {
            rxThread.join(2000);
            physicsThread.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        ByteLink l = link;
        if (l != null) {
            l.close();
        }
    }

    private ServoModule module(int id) {
        ServoModule m = id >= 0 && id < byId.length ? byId[id] : null;
        if (m == null) {
            throw new IllegalArgumentException("module " + id + " is not emulated");
        }
        return m;
    }

    private void rxLoop() {
        byte[] in = new byte[4096];
        long lastByte = System.nanoTime();
        while (running) {
            if (link == null && !reopen()) {
                continue;
            }
            int n;
            try {
                n = link.read(in);
            } catch (IOException e) {
                if (running) {
                    listener.onEvent("emulator: " + e.getMessage() + "; waiting for it to come back");
                }
                link.close();
                link = null;
                deviceGone = true;
                continue;
            }
            long now = System.nanoTime();
            lastPollNanos = now;
            if (pluggedIn(now) && n > 0) {
                lastByte = now;
                wire.feed(in, 0, n);
            } else if (now - lastByte > IDLE_GAP_NANOS && (wire.pending() > 0 || moduleRx.pending() > 0)) {
                wire.idle();
                moduleRx.idle();
            }
        }
    }

    private boolean reopen() {
        LockSupport.parkNanos(REOPEN_NANOS);
        try {
            link = opener.open();
            deviceGone = false;
            listener.onEvent("emulator: serving " + link.name() + " again");
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    /** Applies the unplug schedule; while unplugged, received bytes fall on the floor. */
    private boolean pluggedIn(long now) {
        if (options.unplugAfterS() < 0) {
            return true;
        }
        double t = (now - startNanos) / 1e9;
        boolean out = t >= options.unplugAfterS()
                && (options.unplugForS() < 0 || t < options.unplugAfterS() + options.unplugForS());
        if (out != unplugged) {
            unplugged = out;
            listener.onEvent(String.format("emulator: cable %s at %.3f s", out ? "unplugged" : "plugged back", t));
        }
        return !out;
    }

    /** Frames as they were sent; the fault injector decides what the modules get. */
    private void onWireFrame(int addr, int cmd, byte[] buf, int off, int len) {
        int total = len + Protocol.OVERHEAD;
        if (options.drop() > 0 && random.nextDouble() < options.drop()) {
            synchronized (lock) {
                dropped++;
            }
            return;
        }
        System.arraycopy(buf, off - Protocol.HEADER, scratch, 0, total);
        if (options.corrupt() > 0 && random.nextDouble() < options.corrupt()) {
            synchronized (lock) {
                corrupted++;
            }
            scratch[random.nextInt(total)] ^= (byte) (1 + random.nextInt(255));
        }
        moduleRx.feed(scratch, 0, total);
    }

    private void onModuleFrame(int addr, int cmd, byte[] buf, int off, int len) {
        lastFrameNanos = System.nanoTime();
        ServoModule target = addr == Protocol.BROADCAST ? null : (addr < byId.length ? byId[addr] : null);
        if (addr != Protocol.BROADCAST && target == null) {
            return;
        }
        synchronized (lock) {
            frames++;
            switch (cmd) {
                case Protocol.SETPOINTS -> setpoints(addr, buf, off, len);
                case Protocol.LIMP -> forEach(target, m -> m.safe(Protocol.SAFE_LIMP));
                case Protocol.HOLD -> forEach(target, m -> m.hold(len > 0 && buf[off] == Protocol.HOLD_TARGET));
                case Protocol.ESTOP -> estop(target, len > 0 ? buf[off] : Protocol.SAFE_LIMP);
                case Protocol.RESUME -> forEach(target, m -> {
                    m.estop = false;
                    m.watchdogTripped = false;
                });
                case Protocol.CONFIG -> configure(buf, off, len);
                default -> { }
            }
        }
        if (target != null && (cmd == Protocol.PING || cmd == Protocol.READ)) {
            reply(target, cmd);
        }
    }

    private void setpoints(int addr, byte[] buf, int off, int len) {
        if (addr != Protocol.BROADCAST || len < 5 || (len - 3) % 2 != 0) {
            return;
        }
        int seq = FrameHandler.u16(buf, off);
        int first = buf[off + 2] & 0xFF;
        int count = (len - 3) / 2;
        for (int i = 0; i < modules.length; i++) {
            int slot = modules[i].id - first;
            view[i] = Double.NaN;
            if (slot >= 0 && slot < count) {
                int w = FrameHandler.i16(buf, off + 3 + 2 * slot);
                if (w != Protocol.NO_CHANGE && Protocol.wireInRange(w)) {
                    modules[i].command(w);
                    view[i] = Protocol.fromWire(w);
                }
            }
        }
        listener.onSetpoints(seq, view);
    }

    private void estop(ServoModule target, int mode) {
        long now = System.nanoTime();
        forEach(target, m -> {
            boolean first = !m.estop;
            m.estop = true;
            m.safe(mode);
            if (first) {
                listener.onSafeStop(m.id, now, "emergency stop");
            }
        });
    }

    private void configure(byte[] buf, int off, int len) {
        if (len < 5) {
            return;
        }
        watchdogMs = Math.max(1, FrameHandler.u16(buf, off));
        safeMode = buf[off + 2] == Protocol.SAFE_LIMP ? Protocol.SAFE_LIMP : Protocol.SAFE_HOLD;
        int s = FrameHandler.u16(buf, off + 3);
        speed = s > 0 ? s : options.speedDegPerS();
    }

    private void forEach(ServoModule target, java.util.function.Consumer<ServoModule> action) {
        if (target != null) {
            action.accept(target);
        } else {
            for (ServoModule m : modules) {
                action.accept(m);
            }
        }
    }

    private void reply(ServoModule m, int cmd) {
        if (options.latencyMs() > 0) {
            LockSupport.parkNanos((long) (options.latencyMs() * 1e6));
        }
        int n;
        synchronized (lock) {
            if (cmd == Protocol.PING) {
                n = tx.begin(m.id, Protocol.PONG).putU8(Protocol.VERSION).putU8(Protocol.KIND_SEGMENT)
                        .putU8(m.flags()).putU16(Protocol.toWire(m.angle)).finish();
            } else {
                n = tx.begin(m.id, Protocol.STATUS).putU16(Protocol.toWire(m.angle)).putU8(m.accel(0))
                        .putU8(m.accel(1)).putU8(m.accel(2)).putU8(m.touch).putU8(m.flags())
                        .putU16((int) Math.min(0xFFFF, moduleRx.checksumErrors())).finish();
            }
            if (options.drop() > 0 && random.nextDouble() < options.drop()) {
                dropped++;
                return;
            }
            if (options.corrupt() > 0 && random.nextDouble() < options.corrupt()) {
                corrupted++;
                tx.buffer()[random.nextInt(n)] ^= (byte) (1 + random.nextInt(255));
            }
            replies++;
        }
        try {
            link.write(tx.buffer(), 0, n);
        } catch (IOException e) {
            // The rx loop notices the lost device on its next read and reopens it.
        }
    }

    private void physicsLoop() {
        long last = System.nanoTime();
        while (running) {
            LockSupport.parkNanos(PHYSICS_NANOS);
            long now = System.nanoTime();
            double dt = (now - last) / 1e9;
            last = now;
            // Silence counts only while the rx thread is polling: a stall of this process (GC, a
            // loaded CI machine) must not look like a silent host, as it could not on a PIC.
            boolean silent = (deviceGone ? now : lastPollNanos) - lastFrameNanos > watchdogMs * 1_000_000L;
            synchronized (lock) {
                for (ServoModule m : modules) {
                    if (silent && m.watchdogArmed && !m.watchdogTripped) {
                        m.watchdogTripped = true;
                        m.safe(safeMode);
                        listener.onSafeStop(m.id, now, "watchdog");
                    }
                    m.step(dt, speed);
                }
            }
        }
    }
}
