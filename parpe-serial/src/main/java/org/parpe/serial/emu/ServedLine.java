package org.parpe.serial.emu;

import java.io.IOException;
import java.util.Random;
import java.util.concurrent.locks.LockSupport;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.StreamDecoder;
import org.parpe.serial.text.SerialMsg;

/**
 * What every emulator does with its end of the line, whatever protocol it speaks: a receive thread
 * that reads the device and keeps reopening it when it goes away, the cable-pull schedule, the
 * injected faults (a packet lost, a byte changed, both directions, from one seeded random source)
 * and a physics thread that moves the motors every 2 ms. Bytes from the host go through two
 * decoders of the subclass's protocol: the first sees packets as they were sent and hands each to
 * {@link #relay}, where the fault injector decides what the second, the devices' own, receives, so
 * corrupted packets are really rejected by their checksum. The protocol lives in the subclass.
 */
public abstract class ServedLine implements AutoCloseable {
    private static final long PHYSICS_NANOS = 2_000_000;
    private static final long IDLE_GAP_NANOS = 20_000_000;
    private static final long REOPEN_NANOS = 100_000_000;

    /** Guards the emulated hardware and the counters. */
    protected final Object lock = new Object();
    /** The fault and timing options. */
    protected final EmulatorOptions options;
    /** Where events go. */
    protected final EmulatorListener listener;
    private final LinkOpener opener;
    private final Random random;
    private final long startNanos = System.nanoTime();
    private final Thread rxThread;
    private final Thread physicsThread;
    private volatile boolean running = true;
    private volatile ByteLink link;
    private volatile boolean unplugged;
    private volatile boolean deviceGone;
    private volatile long lastPollNanos = System.nanoTime();
    private long dropped;
    private long corrupted;
    private StreamDecoder asSent;
    private StreamDecoder devices;
    private byte[] scratch;

    /** Serves {@code first} (opened by {@code opener}, which reopens it); call {@link #serve} to start. */
    protected ServedLine(LinkOpener opener, ByteLink first, EmulatorOptions options, EmulatorListener listener,
                         String threadPrefix) {
        this.opener = opener;
        this.link = first;
        this.options = options;
        this.listener = listener;
        this.random = new Random(options.seed());
        rxThread = new Thread(this::rxLoop, threadPrefix + "-rx " + first.name());
        physicsThread = new Thread(this::physicsLoop, threadPrefix + "-physics");
        rxThread.setDaemon(true);
        physicsThread.setDaemon(true);
    }

    /** Starts the receive and physics threads. */
    protected final void serve() {
        rxThread.start();
        physicsThread.start();
    }

    /**
     * The protocol's two decoders (set in the subclass's constructor, before {@link #serve}):
     * {@code asSent} of the host's bytes, which hands each packet to {@link #relay}, and
     * {@code devices} of what the emulated devices receive; {@code maxPacket} bytes the longest.
     */
    protected final void decoders(StreamDecoder asSent, StreamDecoder devices, int maxPacket) {
        this.asSent = asSent;
        this.devices = devices;
        this.scratch = new byte[maxPacket];
    }

    /**
     * A whole packet as the host sent it ({@code len} bytes of {@code b} from {@code off}): lost,
     * or passed to the devices' decoder, maybe with one byte changed, as the fault injector decides.
     */
    protected final void relay(byte[] b, int off, int len) {
        if (lose()) {
            return;
        }
        System.arraycopy(b, off, scratch, 0, len);
        maybeCorrupt(scratch, 0, len);
        devices.feed(scratch, 0, len);
    }

    /** Moves the motors by {@code dt} seconds at time {@code now} (on the physics thread, without the lock). */
    protected abstract void physics(long now, double dt);

    /** True (and counted) when the fault injector loses this packet. */
    protected final boolean lose() {
        if (options.drop() > 0 && random.nextDouble() < options.drop()) {
            synchronized (lock) {
                dropped++;
            }
            return true;
        }
        return false;
    }

    /** Maybe changes one of bytes {@code b[off…off+len)}, as the fault injector decides (counted). */
    protected final void maybeCorrupt(byte[] b, int off, int len) {
        if (options.corrupt() > 0 && random.nextDouble() < options.corrupt()) {
            synchronized (lock) {
                corrupted++;
            }
            b[off + random.nextInt(len)] ^= (byte) (1 + random.nextInt(255));
        }
    }

    /** Sends bytes to the host, unless the cable is out or the device is gone. */
    protected final void send(byte[] b, int off, int len) {
        ByteLink l = link;
        if (l == null || unplugged) {
            return;
        }
        try {
            l.write(b, off, len);
        } catch (IOException e) {
            // The receive thread notices the lost device on its next read and reopens it.
        }
    }

    /** Packets lost on purpose so far. */
    protected final long dropped() {
        synchronized (lock) {
            return dropped;
        }
    }

    /** Packets given a wrong byte on purpose so far. */
    protected final long corrupted() {
        synchronized (lock) {
            return corrupted;
        }
    }

    /**
     * When the host was last listened to: now while the device is gone, else the last read. A
     * stall of this process (GC, a loaded machine) must not look like a silent host.
     */
    protected final long listenedAt(long now) {
        return deviceGone ? now : lastPollNanos;
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

    private void rxLoop() {
        byte[] in = new byte[4096];
        long lastByte = System.nanoTime();
        while (running) {
            ByteLink l = link;
            if (l == null) {
                reopen();
                continue;
            }
            int n;
            try {
                n = l.read(in);
            } catch (IOException e) {
                if (running) {
                    listener.onEvent("emulator: " + SerialMsg.EMU_WAITING.text(e.getMessage()));
                }
                l.close();
                link = null;
                deviceGone = true;
                continue;
            }
            long now = System.nanoTime();
            lastPollNanos = now;
            if (pluggedIn(now) && n > 0) {
                lastByte = now;
                asSent.feed(in, 0, n);
            } else if (now - lastByte > IDLE_GAP_NANOS && (asSent.pending() > 0 || devices.pending() > 0)) {
                // The line fell silent in the middle of a packet: the decoders drop what they hold.
                asSent.idle();
                devices.idle();
            }
        }
    }

    private void reopen() {
        LockSupport.parkNanos(REOPEN_NANOS);
        try {
            link = opener.open();
            deviceGone = false;
            listener.onEvent("emulator: " + SerialMsg.EMU_SERVING_AGAIN.text(link.name()));
        } catch (IOException e) {
            // Not back yet: try again after the pause.
        }
    }

    /** Applies the unplug schedule; while unplugged, received bytes fall on the floor and nothing is sent. */
    private boolean pluggedIn(long now) {
        if (options.unplugAfterS() < 0) {
            return true;
        }
        double t = (now - startNanos) / 1e9;
        boolean out = t >= options.unplugAfterS()
                && (options.unplugForS() < 0 || t < options.unplugAfterS() + options.unplugForS());
        if (out != unplugged) {
            unplugged = out;
            listener.onEvent("emulator: " + (out ? SerialMsg.EMU_UNPLUGGED : SerialMsg.EMU_PLUGGED_BACK)
                    .text(String.format(java.util.Locale.ROOT, "%.3f", t)));
        }
        return !out;
    }

    private void physicsLoop() {
        long last = System.nanoTime();
        while (running) {
            LockSupport.parkNanos(PHYSICS_NANOS);
            long now = System.nanoTime();
            physics(now, (now - last) / 1e9);
            last = now;
        }
    }
}
