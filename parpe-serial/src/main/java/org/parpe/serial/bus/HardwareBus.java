package org.parpe.serial.bus;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.SensorSource;
import org.parpe.core.sensor.SensorTable;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.protocol.Protocol;
import org.parpe.serial.protocol.Command;

/**
 * Drives real modules from a run: a {@link JointSink} that broadcasts each tick's setpoints and a
 * {@link SensorSource} that serves the latest readings. A bus thread owns the wire: it sends the
 * newest setpoints (repeating them as a keepalive for the modules' watchdogs) and reads one
 * module per cycle, round robin, retrying a timed-out read on the next cycle so that setpoints
 * never wait for more than one read timeout. When the modules fall silent or the device goes
 * away it reports at once (the modules stop themselves on their watchdog, in the configured safe
 * mode) and keeps trying to reconnect; when they are back it rediscovers them and resumes.
 */
public final class HardwareBus extends BusThread {
    private static final int BACKOFF_CYCLES = 50;
    private static final int READ_GAP_MS = 2;
    /** Nothing moves yet during discovery, so a module gets more chances than a read in a run. */
    private static final int DISCOVERY_ATTEMPTS = 5;
    private static final int READ_EVERY_WHEN_BUSY = 10;
    private static final long WIRE_POLL_NANOS = 20_000;
    private static final long PROBE_NANOS = 500_000_000;

    private final LinkOpener opener;
    private final Reply reply = new Reply();
    private volatile BusMaster master;
    private RunBuffers buffers;
    private short[] wire;
    private int first;
    private int[] backoff;
    private int readCursor;
    private int readAttempt;
    private int consecutiveTimeouts;
    private int busyCycles;
    private long lastProbe = System.nanoTime();
    private int probeCursor;
    private long lastSend;
    private long reads;
    private long readsRetried;
    private long readFailures;
    private long watchdogResumes;
    private int moduleRxErrors;

    private HardwareBus(LinkOpener opener, BusMaster master, BusConfig config, BusReport report) {
        super(config, report, "module");
        this.opener = opener;
        this.master = master;
    }

    /**
     * Opens the bus; {@code report} receives user messages (faults, recoveries, warnings), from
     * any thread.
     *
     * @throws IOException with a user message when the device cannot be opened
     */
    public static HardwareBus open(LinkOpener opener, BusConfig config, BusReport report) throws IOException {
        return new HardwareBus(opener, new BusMaster(opener.open(), config), config, report);
    }

    /** The device's name. */
    @Override
    public String name() {
        return master.name();
    }

    /**
     * Pings each module of the run (before anything moves), configures every module's watchdog
     * and safe mode and clears old emergency stops. Only the modules found are driven.
     */
    public Discovery discover(int[] moduleIds) throws IOException {
        buffers = new RunBuffers(moduleIds);
        backoff = new int[moduleIds.length];
        int lo = Integer.MAX_VALUE;
        int hi = -1;
        for (int id : moduleIds) {
            if (id <= Protocol.MAX_MODULE_ID) {
                lo = Math.min(lo, id);
                hi = Math.max(hi, id);
            }
        }
        first = hi < 0 ? 0 : lo;
        wire = new short[Math.max(1, hi - first + 1)];
        java.util.Arrays.fill(wire, Protocol.NO_CHANGE);
        Discovery d = ping(master, buffers.ids);
        master.sendConfig(config.watchdogMs(), config.safeMode(), 0);
        master.send(Protocol.BROADCAST, Command.RESUME);
        return d;
    }

    private Discovery ping(BusMaster m, int[] ids) throws IOException {
        List<Integer> found = new ArrayList<>();
        List<Integer> missing = new ArrayList<>();
        List<Integer> unaddressable = new ArrayList<>();
        for (int i = 0; i < ids.length; i++) {
            if (ids[i] > Protocol.MAX_MODULE_ID) {
                unaddressable.add(ids[i]);
            } else if (m.ping(ids[i], reply, Math.max(DISCOVERY_ATTEMPTS, config.retries() + 1))) {
                found.add(ids[i]);
                buffers.driven[i] = true;
                buffers.store(i, reply, false);
            } else {
                buffers.driven[i] = false;
                missing.add(ids[i]);
            }
        }
        return new Discovery(found, missing, unaddressable);
    }

    @Override
    public void start(RunInfo info) {
        if (buffers == null || !java.util.Arrays.equals(info.moduleIds(), buffers.ids)) {
            throw new IllegalStateException("discover() must be called with the run's module IDs before start");
        }
        answeredNow();
        startThread("bus " + master.name());
    }

    @Override
    public void accept(long tick, double time, double[] commanded) {
        buffers.accept(tick, commanded, report::problem);
    }

    @Override
    public void read(double time, SensorTable table) {
        buffers.copyTo(table);
    }

    /** The last measured angle of the module at {@code index} (run order), NaN before any. */
    public double measuredAngle(int index) {
        return buffers.measuredAngle(index);
    }

    /** Sends the last setpoints, then tells every module to finish its move and hold (watchdogs off). */
    @Override
    protected void sendFinalHold() throws IOException {
        // Three times: these frames get no reply, and a lost final HOLD would let the watchdogs trip.
        int seq = buffers.take(wire, first, true);
        for (int i = 0; i < 3; i++) {
            if (seq >= 0) {
                master.sendSetpoints(seq, first, wire, wire.length);
            }
            master.sendHold(Protocol.BROADCAST, true);
        }
    }

    @Override
    protected IOException linkError() {
        return master.linkError();
    }

    /**
     * Broadcasts ESTOP (three times, in case one is lost); every module stops in the safe mode and
     * ignores setpoints until the next run.
     */
    @Override
    protected String sendEmergencyStop() throws IOException {
        BusMaster m = master;
        for (int i = 0; i < 3; i++) {
            m.sendEmergencyStop(config.safeMode());
        }
        m.drain(100);
        return "modules " + config.safeMode().name().toLowerCase() + " until the next run";
    }

    @Override
    public String summary() {
        BusMaster.Counters c = master.counters();
        return String.format(java.util.Locale.ROOT, "bus %s: %d frames sent, %d reads (%d timeouts, %d retried ok, "
                + "%d failed), %d bad checksums received, modules rejected %d frames, %d setpoints clamped, "
                + "%d watchdog stops, %d disconnects", master.name(), c.framesSent(), reads, c.timeouts(), readsRetried,
                readFailures, c.checksumErrors(), moduleRxErrors, buffers == null ? 0 : buffers.clamps(),
                watchdogResumes, disconnects());
    }

    /**
     * One cycle: setpoints if new or due as keepalive, then one read attempt. While setpoints
     * come faster than the line carries them, only every {@value #READ_EVERY_WHEN_BUSY}th cycle
     * reads, so that setpoints keep most of the wire.
     */
    @Override
    protected void cycle() throws IOException, InterruptedException {
        int queued = master.pendingOutput();
        if (queued > 0) {
            // The line is still busy with the last frame: wait until it drains rather than queue a stale one.
            LockSupport.parkNanos(Math.max(WIRE_POLL_NANOS, (long) (queued * 10e9 / config.baud()) - WIRE_POLL_NANOS));
            return;
        }
        long now = System.nanoTime();
        boolean keepalive = now - lastSend > TimeUnit.MILLISECONDS.toNanos(config.keepaliveMs());
        int seq = buffers.take(wire, first, keepalive);
        if (seq >= 0) {
            master.sendSetpoints(seq, first, wire, wire.length);
            lastSend = now;
        }
        busyCycles = seq >= 0 ? busyCycles + 1 : 0;
        probeMissing(now);
        boolean read = (busyCycles == 0 || busyCycles % READ_EVERY_WHEN_BUSY == 0) && readOne();
        // A late reply, one that came after its read had timed out, still shows that the bus is alive.
        answeredAt(master.lastReplyNanos());
        if (consecutiveTimeouts > config.retries() && deadFor()) {
            silent(master.name(), whileLost());
        } else if (seq < 0) {
            // Reads fill the gaps between ticks, at a bounded rate so the bus has room to spare.
            buffers.awaitFresh(read ? READ_GAP_MS : config.keepaliveMs());
        }
    }

    /** One attempt at reading the module under the cursor; false when nothing is driven. */
    private boolean readOne() throws IOException {
        int n = buffers.ids.length;
        for (int k = 0; k < n && readAttempt == 0; k++) {
            if (buffers.driven[readCursor] && (backoff[readCursor] == 0 || --backoff[readCursor] == 0)) {
                break;
            }
            readCursor = (readCursor + 1) % n;
        }
        if (!buffers.driven[readCursor] || backoff[readCursor] > 0) {
            return false;
        }
        int id = buffers.ids[readCursor];
        if (master.read(id, reply, 1)) {
            answeredNow();
            consecutiveTimeouts = 0;
            reads++;
            readsRetried += readAttempt > 0 ? 1 : 0;
            buffers.store(readCursor, reply, true);
            moduleRxErrors = Math.max(moduleRxErrors, reply.rxErrors);
            if ((reply.flags & Protocol.Flag.WATCHDOG.bit()) != 0) {
                watchdogResumes++;
                watchdogResumed(id, config.watchdogMs());
                master.send(id, Command.RESUME);
            }
        } else {
            consecutiveTimeouts++;
            if (++readAttempt <= config.retries()) {
                return true;
            }
            readFailures++;
            backoff[readCursor] = BACKOFF_CYCLES;
            report.problem("bus: module " + id + " did not answer " + (config.retries() + 1)
                    + " reads; reading it less often");
        }
        readAttempt = 0;
        readCursor = (readCursor + 1) % n;
        return true;
    }

    /** Every half second, pings one module that is not driven; one that answers is driven again. */
    private void probeMissing(long now) throws IOException {
        if (now - lastProbe < PROBE_NANOS) {
            return;
        }
        lastProbe = now;
        int n = buffers.ids.length;
        for (int k = 0; k < n; k++) {
            probeCursor = (probeCursor + 1) % n;
            int id = buffers.ids[probeCursor];
            if (!buffers.driven[probeCursor] && id <= Protocol.MAX_MODULE_ID) {
                if (master.ping(id, reply, 1)) {
                    answeredNow();
                    buffers.store(probeCursor, reply, false);
                    buffers.driven[probeCursor] = true;
                    master.send(id, Command.RESUME);
                    report.note("bus: module " + id + " answers now; driving it");
                }
                return;
            }
        }
    }

    @Override
    protected String whileLost() {
        return "modules stop on their watchdog (" + config.safeMode().name().toLowerCase() + ") within "
                + config.watchdogMs() + " ms";
    }

    @Override
    protected void reopenDevice() throws IOException {
        master = new BusMaster(opener.open(), config);
    }

    @Override
    protected void closeDevice() {
        master.close();
    }

    @Override
    protected int lookCount() {
        return buffers.ids.length;
    }

    @Override
    protected boolean answers(int i) throws IOException {
        return buffers.ids[i] <= Protocol.MAX_MODULE_ID && master.ping(buffers.ids[i], reply, 1);
    }

    /** Pings every module again, re-sends CONFIG and RESUME, reads from the start. */
    @Override
    protected String setUpAgain() throws IOException {
        Discovery d = ping(master, buffers.ids);
        lastProbe = System.nanoTime();
        master.sendConfig(config.watchdogMs(), config.safeMode(), 0);
        master.send(Protocol.BROADCAST, Command.RESUME);
        java.util.Arrays.fill(backoff, 0);
        readAttempt = 0;
        consecutiveTimeouts = 0;
        return String.format(java.util.Locale.ROOT, " (%d of %d answer%s)", d.found().size(), buffers.ids.length,
                d.missing().isEmpty() ? "" : ", missing " + d.missing());
    }
}
