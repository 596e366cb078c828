package org.parpe.serial.servo.run;

import org.parpe.core.text.Message;
import org.parpe.serial.text.SerialMsg;
import java.io.IOException;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.parpe.core.sensor.Channel;
import org.parpe.core.run.RunInfo;
import org.parpe.core.sensor.SensorTable;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.BusReport;
import org.parpe.serial.bus.BusThread;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.profile.HardwareProfile;

/**
 * Drives the servos of a hardware profile from a run, on every protocol: G1 modules (the command
 * line's {@code --port} builds their profile from the script's modules), Dynamixel and Feetech.
 * The engine's setpoints are clamped to each servo's limits (warned once per module, counted
 * always) and turned into goal ticks; a bus thread sends them in one packet, repeats them as a
 * keepalive, and reads present positions (and, from G1 modules, their accelerometers and touch
 * sensors), which become the modules' measured values: every servo each read cycle where the
 * protocol has a group read; one servo per read cycle, round robin, where it has none (G1), a
 * timed-out read retried on the next cycles and a servo that keeps timing out read less often.
 * Servos that did not answer discovery are pinged every half second and driven, from where they
 * are, once they answer. A servo reporting a fault (overload, overheating, voltage) is reported in
 * words. When every servo falls silent or the device goes away, the driver reports it at once,
 * keeps looking and resumes when they are back.
 */
public final class ServoDriver extends BusThread {
    private static final int READ_EVERY_WHEN_BUSY = 10;
    private static final int READ_GAP_MS = 2;
    private static final int WATCHDOG_CHECK_MS = 100;
    /** Read cycles a servo that did not answer its reads and their retries is skipped. */
    private static final int BACKOFF_CYCLES = 50;
    private static final long PROBE_NANOS = 500_000_000;
    private static final long WIRE_POLL_NANOS = 20_000;

    private final LinkOpener opener;
    private final HardwareProfile profile;
    private volatile ServoBus bus;
    private final ServoSet set;
    private long lastSend;
    private int failedReads;
    private int busyCycles;
    private long reads;
    private long readsRetried;
    private long readFailures;
    private long faults;
    private long watchdogResumes;
    private long lastWatchdogCheck;
    private int watchdogCursor;
    /** Reads one servo per read cycle (the protocol has no group read), this one next. */
    private final boolean roundRobin;
    private int readCursor = -1;
    /** Failed attempts at reading the servo under the cursor. */
    private int readAttempt;
    /** Per mapped servo: read cycles it is still skipped for. */
    private final int[] backoff;
    private final ServoSetUp setUp;
    private long lastProbe = System.nanoTime();
    private int probeCursor;
    private final int[] oneId = new int[1];
    private final ServoModel[] oneModel = new ServoModel[1];
    private final double[] oneDegrees = new double[1];
    private final int[] oneError = new int[1];

    private ServoDriver(LinkOpener opener, ServoBus bus, BusConfig config, HardwareProfile profile, int[] runModules,
                        BusReport report) {
        super(config, report, profile.protocol().modules());
        this.opener = opener;
        this.bus = bus;
        this.profile = profile;
        this.set = new ServoSet(profile, runModules);
        this.roundRobin = !profile.protocol().groupRead();
        this.backoff = new int[set.size()];
        this.setUp = new ServoSetUp(set, profile, config, report);
    }

    /**
     * Opens the bus of {@code profile} through {@code opener} for a run of {@code runModules}.
     *
     * @throws IOException with a user message when the device cannot be opened
     */
    public static ServoDriver open(LinkOpener opener, BusConfig config, HardwareProfile profile, int[] runModules,
                                   BusReport report) throws IOException {
        ServoBus b = org.parpe.serial.servo.host.ServoBuses.open(profile.protocol(), opener, config);
        return new ServoDriver(opener, b, config, profile, runModules, report);
    }

    /** The device's name. */
    @Override
    public String name() {
        return bus.name();
    }

    /**
     * Pings every mapped servo of the run and makes the found ones hold where they are, within
     * their limits, with their torque on (read back); {@link #limp} lists those whose torque did
     * not come on. The servos' watchdog is armed by {@link #start}, when traffic begins: armed
     * here, it would trip during whatever the run sets up in between. Returns the modules whose
     * servo answered as the model the profile says.
     */
    public List<Integer> discover() throws IOException {
        return setUp.discover(bus);
    }

    /** Modules whose servo answered discovery as another model than the profile's, and is not driven. */
    public List<Integer> answeredAsOtherModel() {
        return setUp.answeredAsOtherModel();
    }

    /** Modules whose servo answered but stayed limp (torque off, or its position unknown) after set-up. */
    public List<Integer> limp() {
        return setUp.limp();
    }

    /** Arms the servos' own watchdog, the last step of set-up, just before traffic keeps it fed. */
    private void armWatchdog() throws IOException {
        int n = set.pack();
        report.note("bus: " + bus.watchdog(set.ids, set.models, n, profile.watchdogMs(),
                profile.onFault() == SafeMode.LIMP));
    }

    /** Modules of the run without a servo in the profile. */
    public List<Integer> unmapped() {
        return set.unmapped();
    }

    @Override
    public void start(RunInfo info) {
        try {
            armWatchdog();
        } catch (IOException e) {
            report.problem("bus: " + SerialMsg.WATCHDOG_NOT_ARMED.text(e.getMessage()));
        }
        answeredNow();
        startThread("servo bus " + bus.name());
    }

    @Override
    public void accept(long tick, double time, double[] commanded) {
        set.accept(tick, commanded, report::problem);
    }

    @Override
    public void read(double time, SensorTable table) {
        set.copyTo(table);
    }

    /** The last measured joint angle of run module {@code index}, NaN before any. */
    public double measuredAngle(int index) {
        return set.measured(index);
    }

    /** The last goals and a hold with the watchdog off, in the protocol's way ({@link ServoBus#finalHold}). */
    @Override
    protected void sendFinalHold() throws IOException {
        int n = set.pack();
        boolean goals = set.takeGoals(true);
        bus.goalSequence(set.goalSeq());
        bus.finalHold(set.ids, set.models, goals ? set.goals : null, n);
    }

    @Override
    protected IOException linkError() {
        return bus.linkError();
    }

    /** Every driven servo stops in the profile's safe mode. */
    @Override
    protected String sendEmergencyStop() throws IOException {
        return bus.emergencyStop(set.ids, set.models, set.pack(), profile.onFault() == SafeMode.LIMP);
    }

    @Override
    public String summary() {
        ServoBus.Counters c = bus.counters();
        ServoProtocol p = profile.protocol();
        boolean g1 = p.modules();
        Message rejected = c.rejected() < 0 ? Message.EMPTY
                : Message.of(g1 ? SerialMsg.REJECTED_BY_MODULES : SerialMsg.REJECTED_BY_SERVOS, c.rejected());
        return SerialMsg.SUMMARY.text(bus.name(), p.key(),
                Message.of(p.controlTable() ? SerialMsg.SENT_PACKETS : SerialMsg.SENT_FRAMES, c.packetsSent()),
                reads, c.timeouts(), readsRetried, readFailures, c.checksumErrors(), rejected, set.clamps(),
                Message.of(g1 ? SerialMsg.FAULTS_MODULE : SerialMsg.FAULTS_SERVO, faults), watchdogResumes, disconnects());
    }

    /** Goals when new or due as keepalive, then a read unless goals saturate the line. */
    @Override
    protected void cycle() throws IOException, InterruptedException {
        int queued = bus.pendingOutput();
        if (queued > 0) {
            // The line is still busy with the last packet: wait until it drains rather than queue a
            // stale one, waking a little early so that the next one follows without a gap.
            LockSupport.parkNanos(Math.max(WIRE_POLL_NANOS, (long) (queued * 10e9 / config.baud()) - WIRE_POLL_NANOS));
            return;
        }
        long now = System.nanoTime();
        int n = set.pack();
        boolean keepalive = now - lastSend > TimeUnit.MILLISECONDS.toNanos(config.keepaliveMs());
        boolean sent = set.takeGoals(keepalive);
        busyCycles = sent ? busyCycles + 1 : 0;
        boolean read = busyCycles == 0 || busyCycles % READ_EVERY_WHEN_BUSY == 0;
        if (sent) {
            lastSend = now;
            bus.goalSequence(set.goalSeq());
            if (!read || roundRobin) {
                bus.writeGoals(set.ids, set.models, set.goals, n);
            }
        }
        probeMissing(now);
        int answered = !read ? -1 : roundRobin ? readNext(n)
                : sent ? bus.writeGoalsAndRead(set.ids, set.models, set.goals, n, set.degrees, set.errors)
                : bus.readPositions(set.ids, set.models, n, set.degrees, set.errors);
        if (answered > 0) {
            reads++;
            answeredNow();
            failedReads = 0;
            if (!roundRobin) {
                faults += set.storeReadings(0, n, bus, this::fault);
                checkWatchdog(n);
            }
        } else if (answered == 0 && n > 0) {
            readFailures += roundRobin ? 0 : 1;
            // Dead: no answer for the dead-bus time and more failed reads in a row than retries.
            if (++failedReads > config.retries() && deadFor()) {
                silent(bus.name(), bus.silenced(set.ids, set.models, n, profile.watchdogMs(),
                        profile.onFault() == SafeMode.LIMP));
                return;
            }
        }
        if (!sent) {
            // Reads fill the gaps between ticks, at a bounded rate so the bus has room to spare.
            set.awaitFresh(answered >= 0 ? READ_GAP_MS : config.keepaliveMs());
        }
    }

    /**
     * Reads the present position of one servo, round robin, and stores it; a servo whose reply
     * says it stopped on its own watchdog is resumed at once. A read that times out is tried
     * again on the next read cycles, up to the configured retries; then the servo is skipped for
     * {@value #BACKOFF_CYCLES} read cycles (said each time it is put back), so that one silent servo does not cost
     * every cycle a timeout. Returns 1 when it answered, 0 when not, −1 when nothing was read.
     */
    private int readNext(int n) throws IOException {
        if (n == 0) {
            return -1;
        }
        if (readAttempt == 0 || readCursor >= n) {
            readAttempt = 0;
            int k = -1;
            for (int t = 0; t < n && k < 0; t++) {
                readCursor = (readCursor + 1) % n;
                int j = set.slotOf(readCursor);
                if (backoff[j] == 0 || --backoff[j] == 0) {
                    k = readCursor;
                }
            }
            if (k < 0) {
                return -1;
            }
        }
        int k = readCursor;
        oneId[0] = set.ids[k];
        oneModel[0] = set.models[k];
        int answered = bus.readPositions(oneId, oneModel, 1, oneDegrees, oneError);
        set.errors[k] = oneError[0];
        if (answered > 0) {
            readsRetried += readAttempt > 0 ? 1 : 0;
            readAttempt = 0;
            set.degrees[k] = oneDegrees[0];
            faults += set.storeReadings(k, k + 1, bus, this::fault);
            resumeIfTripped(k);
        } else if (++readAttempt > config.retries()) {
            readAttempt = 0;
            readFailures++;
            backoff[set.slotOf(k)] = BACKOFF_CYCLES;
            report.problem("bus: " + SerialMsg.DID_NOT_ANSWER_READS.text(ServoSetUp.who(profile.protocol(), set.mappingAt(k)),
                    config.retries() + 1));
        }
        return answered;
    }

    /**
     * Every half second, pings one mapped servo that is not driven (it did not answer discovery);
     * one that answers as its model is set up and driven from then on ({@link ServoSetUp#bringIn}).
     */
    private void probeMissing(long now) throws IOException {
        if (now - lastProbe < PROBE_NANOS) {
            return;
        }
        lastProbe = now;
        int size = set.size();
        for (int t = 0; t < size; t++) {
            probeCursor = (probeCursor + 1) % size;
            if (setUp.missing(probeCursor)) {
                if (setUp.bringIn(bus, probeCursor) >= 0) {
                    answeredNow();
                }
                return;
            }
        }
    }

    /** Every {@value #WATCHDOG_CHECK_MS} ms, one servo: resumed if it stopped on its own watchdog. */
    private void checkWatchdog(int n) throws IOException {
        long now = System.nanoTime();
        if (n == 0 || profile.watchdogMs() <= 0 || now - lastWatchdogCheck < WATCHDOG_CHECK_MS * 1_000_000L) {
            return;
        }
        lastWatchdogCheck = now;
        resumeIfTripped(watchdogCursor++ % n);
    }

    /** Packed servo {@code k} is resumed if its last reply said it stopped on its own watchdog. */
    private void resumeIfTripped(int k) throws IOException {
        if (bus.resumeIfTripped(set.ids[k], set.models[k], set.errors[k], profile.watchdogMs())) {
            watchdogResumes++;
            watchdogResumed(set.ids[k], profile.watchdogMs());
        }
    }

    private void fault(String message) {
        report.problem("bus: " + message);
    }


    @Override
    protected String whileLost() {
        return bus.whileLost(profile.watchdogMs(), profile.onFault() == SafeMode.LIMP);
    }

    @Override
    protected void reopenDevice() throws IOException {
        bus = org.parpe.serial.servo.host.ServoBuses.open(profile.protocol(), opener, config);
    }

    @Override
    protected void closeDevice() {
        bus.close();
    }

    @Override
    protected int lookCount() {
        return set.pack();
    }

    @Override
    protected boolean answers(int i) throws IOException {
        return bus.ping(set.ids[i], 1) >= 0;
    }

    /** The safe start again (present positions held, torque read back), then the watchdog. */
    @Override
    protected Message setUpAgain() throws IOException {
        Message detail = setUp.holdAgain(bus);
        armWatchdog();
        failedReads = 0;
        readAttempt = 0;
        java.util.Arrays.fill(backoff, 0);
        lastProbe = System.nanoTime();
        return detail;
    }
}
