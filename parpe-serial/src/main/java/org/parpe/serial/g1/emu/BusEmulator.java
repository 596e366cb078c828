package org.parpe.serial.g1.emu;

import java.io.IOException;
import java.util.Arrays;
import java.util.concurrent.locks.LockSupport;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.emu.ServedLine;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.g1.FrameDecoder;
import org.parpe.serial.g1.FrameEncoder;
import org.parpe.serial.g1.FrameHandler;
import org.parpe.serial.g1.Protocol;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.g1.Command;
import org.parpe.serial.text.SerialMsg;

/**
 * Emulates a chain of modules on the far end of a serial link, byte for byte as the protocol
 * says. Incoming bytes pass a perfect decoder, then the fault injector (which drops a frame or
 * changes one of its bytes), then the modules' own decoder, so corrupted frames are really
 * rejected by their CRC. A physics thread moves the servos at their speed limit every 2 ms and
 * trips each module's watchdog when no frame arrived for the configured time. If the device
 * goes away, the emulator keeps reopening it.
 */
public final class BusEmulator extends ServedLine {
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

    private final ServoModule[] modules;
    private final ServoModule[] byId = new ServoModule[256];
    private final double[] view;
    private final FrameDecoder wire = new FrameDecoder(this::onWireFrame);
    private final FrameDecoder moduleRx = new FrameDecoder(this::onModuleFrame);
    private final FrameEncoder tx = new FrameEncoder();
    private volatile long lastFrameNanos = System.nanoTime();
    private int watchdogMs = 50;
    private int safeMode = SafeMode.HOLD.wire();
    private double speed;
    private long frames;
    private long replies;

    private BusEmulator(LinkOpener opener, ByteLink first, EmulatorOptions options, EmulatorListener listener) {
        super(opener, first, options, listener, "emulator");
        this.speed = options.speedDegPerS();
        int[] ids = options.modules().clone();
        Arrays.sort(ids);
        modules = new ServoModule[ids.length];
        for (int i = 0; i < ids.length; i++) {
            modules[i] = new ServoModule(ids[i]);
            byId[ids[i]] = modules[i];
        }
        view = new double[ids.length];
        decoders(wire, moduleRx, Protocol.MAX_FRAME);
    }

    /** Opens the device through {@code opener} (errors surface here) and starts serving it. */
    public static BusEmulator start(LinkOpener opener, EmulatorOptions options, EmulatorListener listener)
            throws IOException {
        BusEmulator e = new BusEmulator(opener, opener.open(), options, listener);
        e.serve();
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
            return new Stats(frames, dropped(), corrupted(), moduleRx.checksumErrors(), replies);
        }
    }


    private ServoModule module(int id) {
        ServoModule m = id >= 0 && id < byId.length ? byId[id] : null;
        if (m == null) {
            throw new IllegalArgumentException(SerialMsg.NOT_EMULATED.text(SerialMsg.WHO_MODULE.text(id)));
        }
        return m;
    }


    /** Frames as they were sent; the fault injector decides what the modules get. */
    private void onWireFrame(int addr, int cmd, byte[] buf, int off, int len) {
        relay(buf, off - Protocol.HEADER, len + Protocol.OVERHEAD);
    }

    private void onModuleFrame(int addr, int cmd, byte[] buf, int off, int len) {
        lastFrameNanos = System.nanoTime();
        ServoModule target = addr == Protocol.BROADCAST ? null : (addr < byId.length ? byId[addr] : null);
        if (addr != Protocol.BROADCAST && target == null) {
            return;
        }
        Command command = Command.of(cmd);
        synchronized (lock) {
            frames++;
            if (command != null) {
                switch (command) {
                    case SETPOINTS -> setpoints(addr, buf, off, len);
                    case LIMP -> forEach(target, m -> m.safe(SafeMode.LIMP.wire()));
                    case HOLD -> forEach(target, m -> m.hold(len > 0 && buf[off] == Protocol.HOLD_TARGET));
                    case ESTOP -> estop(target, len > 0 ? buf[off] : SafeMode.LIMP.wire());
                    case RESUME -> forEach(target, m -> {
                        m.estop = false;
                        m.watchdogTripped = false;
                    });
                    case CONFIG -> configure(buf, off, len);
                    default -> { }
                }
            }
        }
        if (target != null && (command == Command.PING || command == Command.READ)) {
            reply(target, command);
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
                listener.onSafeStop(m.id, now, SerialMsg.EMU_ESTOP.text());
            }
        });
    }

    private void configure(byte[] buf, int off, int len) {
        if (len < 5) {
            return;
        }
        watchdogMs = Math.max(1, FrameHandler.u16(buf, off));
        safeMode = buf[off + 2] == SafeMode.LIMP.wire() ? SafeMode.LIMP.wire() : SafeMode.HOLD.wire();
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

    private void reply(ServoModule m, Command cmd) {
        if (options.latencyMs() > 0) {
            LockSupport.parkNanos((long) (options.latencyMs() * 1e6));
        }
        int n;
        synchronized (lock) {
            if (cmd == Command.PING) {
                n = tx.begin(m.id, Command.PONG).putU8(Protocol.VERSION).putU8(Protocol.KIND_SEGMENT)
                        .putU8(m.flags()).putU16(Protocol.toWire(m.angle)).finish();
            } else {
                n = tx.begin(m.id, Command.STATUS).putU16(Protocol.toWire(m.angle)).putU8(m.accel(0))
                        .putU8(m.accel(1)).putU8(m.accel(2)).putU8(m.touch).putU8(m.flags())
                        .putU16((int) Math.min(0xFFFF, moduleRx.checksumErrors())).finish();
            }
            if (lose()) {
                return;
            }
            maybeCorrupt(tx.buffer(), 0, n);
            replies++;
        }
        send(tx.buffer(), 0, n);
    }

    @Override
    protected void physics(long now, double dt) {
        // Silence counts only while the rx thread is polling: a stall of this process (GC, a
        // loaded CI machine) must not look like a silent host, as it could not on a PIC.
        boolean silent = listenedAt(now) - lastFrameNanos > watchdogMs * 1_000_000L;
        synchronized (lock) {
            for (ServoModule m : modules) {
                if (silent && m.watchdogArmed && !m.watchdogTripped) {
                    m.watchdogTripped = true;
                    m.safe(safeMode);
                    listener.onSafeStop(m.id, now, SerialMsg.EMU_WATCHDOG.text());
                }
                m.step(dt, speed);
            }
        }
    }
}
