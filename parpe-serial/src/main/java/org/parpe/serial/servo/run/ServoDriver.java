package org.parpe.serial.servo.run;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
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
import org.parpe.serial.servo.profile.ServoMapping;

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
    /** Per mapped servo: answered as another model; never driven, never probed. */
    private final boolean[] otherModel;
    private long lastProbe = System.nanoTime();
    private int probeCursor;
    private final int[] oneId = new int[1];
    private final ServoModel[] oneModel = new ServoModel[1];
    private final double[] oneDegrees = new double[1];
    private final int[] oneError = new int[1];
    private final int[] oneGoal = new int[1];
    private final List<Integer> answeredOther = new ArrayList<>();
    private final List<Integer> limp = new ArrayList<>();

    private ServoDriver(LinkOpener opener, ServoBus bus, BusConfig config, HardwareProfile profile, int[] runModules,
                        BusReport report) {
        super(config, report, profile.protocol().unit());
        this.opener = opener;
        this.bus = bus;
        this.profile = profile;
        this.set = new ServoSet(profile, runModules);
        this.roundRobin = !profile.protocol().groupRead();
        this.backoff = new int[set.size()];
        this.otherModel = new boolean[set.size()];
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
        List<Integer> found = new ArrayList<>();
        answeredOther.clear();
        for (int j = 0; j < set.size(); j++) {
            ServoMapping m = set.mapping(j);
            int model = bus.ping(m.servo(), Math.max(5, config.retries() + 1));
            set.driven[j] = model >= 0 && compatible(m, model);
            otherModel[j] = model >= 0 && !set.driven[j];
            if (set.driven[j]) {
                found.add(m.module());
            } else if (model >= 0) {
                answeredOther.add(m.module());
            }
        }
        if (!found.isEmpty()) {
            setUp();
        }
        return found;
    }

    /** Modules whose servo answered discovery as another model than the profile's, and is not driven. */
    public List<Integer> answeredAsOtherModel() {
        return List.copyOf(answeredOther);
    }

    /** Modules whose servo answered but stayed limp (torque off, or its position unknown) after set-up. */
    public List<Integer> limp() {
        return List.copyOf(limp);
    }

    /** A servo in messages: {@code servo 3 (module 1)}, or {@code module 1} where they are one (G1 by ID). */
    private String who(ServoMapping m) {
        return profile.protocol() == ServoProtocol.G1 && m.servo() == m.module() ? "module " + m.module()
                : "servo " + m.servo() + " (module " + m.module() + ")";
    }

    /**
     * Whether a servo reporting {@code model} can be driven as the profile's model says: the same
     * model, or one with the same control table and units (warned). Another one would get goals
     * at the wrong address or in the wrong unit, so it is not driven.
     */
    private boolean compatible(ServoMapping m, int model) {
        if (model == 0 || model == m.model().number()) {
            return true;
        }
        ServoModel actual = ServoModel.of(profile.protocol(), model);
        boolean same = actual != null && actual.registers() == m.model().registers()
                && actual.resolution() == m.model().resolution() && actual.rangeDeg() == m.model().rangeDeg()
                && actual.centre() == m.model().centre();
        report.problem(String.format(Locale.ROOT, "bus: %s is %s, the profile says %s at %s; %s",
                who(m), actual == null ? "of unknown model " + model : "an " + actual.label(),
                m.model().label(), m.where(), same ? "driving it anyway (same control table and units)"
                        : "it will not move (correct the model in the profile)"));
        return same;
    }

    /**
     * Present positions (retried until each servo has answered), goals that hold each servo
     * there clamped into its limits, torque on, and torque read back: a servo whose torque does
     * not come on is limp while the run drives it, which the user must hear about.
     */
    private void setUp() throws IOException {
        int n = set.pack();
        int attempts = Math.max(5, config.retries() + 1);
        boolean[] known = new boolean[n];
        for (int a = 0, left = n; a < attempts && left > 0; a++) {
            bus.readPositions(set.ids, set.models, n, set.degrees, set.errors);
            set.storeReadings(0, n, bus, this::fault);
            for (int k = 0; k < n; k++) {
                if (!known[k] && set.errors[k] != ServoBus.NO_REPLY) {
                    known[k] = true;
                    left--;
                }
            }
        }
        limp.clear();
        for (int k = 0; k < n; k++) {
            if (!holdFound(k, known[k], attempts)) {
                limp.add(set.mappingAt(k).module());
            }
        }
    }

    /**
     * Packed servo {@code k}, its position {@code known} or not, is held there, torque on and read
     * back; false (reported) when its position is unknown or its torque did not come on.
     */
    private boolean holdFound(int k, boolean known, int attempts) throws IOException {
        ServoMapping m = set.mappingAt(k);
        if (!known) {
            report.problem(String.format(Locale.ROOT, "bus: %s answered the ping but not %d reads of its position; "
                    + "its torque stays off and it will not follow the run", who(m), attempts));
            return false;
        }
        oneId[0] = m.servo();
        oneModel[0] = m.model();
        oneGoal[0] = set.holdTicks(k);
        int state = 0;
        for (int a = 0; a < attempts && state != 1; a++) {
            bus.holdAt(oneId, oneModel, oneGoal, 1);
            state = bus.torqueState(m.servo(), m.model(), 2);
        }
        if (state != 1) {
            report.problem(String.format(Locale.ROOT, "bus: %s did not turn its torque on (Torque Enable %s after %d "
                    + "tries); it is limp and will not follow the run", who(m),
                    state == 0 ? "read back 0" : "could not be read back", attempts));
        }
        return state == 1;
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
            report.problem("bus: could not arm the servos' watchdog: " + e.getMessage());
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
        return String.format(Locale.ROOT, "bus %s (%s): %d %ss sent, %d reads (%d timeouts, %d retried ok, %d failed), "
                + "%d bad checksums received, %s%d setpoints clamped, %d %s faults, %d watchdog stops, %d disconnects",
                bus.name(), p.key(), c.packetsSent(), p.packet(), reads, c.timeouts(), readsRetried, readFailures,
                c.checksumErrors(), c.rejected() < 0 ? "" : p.unit() + "s rejected " + c.rejected() + " frames, ",
                set.clamps(), faults, p.unit(), watchdogResumes, disconnects());
    }

    /** Goals when new or due as keepalive, then a read unless goals saturate the line. */
    @Override
    protected void cycle() throws IOException, InterruptedException {
        int queued = bus.pendingOutput();
        if (queued > 0) {
            LockSupport.parkNanos((long) (queued * 10e9 / config.baud()));
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
     * {@value #BACKOFF_CYCLES} read cycles (said once), so that one silent servo does not cost
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
            report.problem("bus: " + who(set.mappingAt(k)) + " did not answer " + (config.retries() + 1)
                    + " reads; reading it less often");
        }
        return answered;
    }

    /**
     * Every half second, pings one mapped servo that is not driven (it did not answer discovery);
     * one that answers as its model is set up as at discovery (held where it is, torque on, its
     * watchdog armed) and driven from then on.
     */
    private void probeMissing(long now) throws IOException {
        if (now - lastProbe < PROBE_NANOS) {
            return;
        }
        lastProbe = now;
        int size = set.size();
        for (int t = 0; t < size; t++) {
            probeCursor = (probeCursor + 1) % size;
            int j = probeCursor;
            if (set.driven[j] || otherModel[j]) {
                continue;
            }
            ServoMapping m = set.mapping(j);
            int model = bus.ping(m.servo(), 1);
            if (model < 0) {
                return;
            }
            answeredNow();
            if (!compatible(m, model)) {
                otherModel[j] = true;
                return;
            }
            oneId[0] = m.servo();
            oneModel[0] = m.model();
            if (bus.readPositions(oneId, oneModel, 1, oneDegrees, oneError) == 0) {
                return;
            }
            set.driven[j] = true;
            int k = indexOfSlot(set.pack(), j);
            set.degrees[k] = oneDegrees[0];
            set.errors[k] = oneError[0];
            set.storeReadings(k, k + 1, bus, this::fault);
            if (!holdFound(k, true, 2)) {
                set.driven[j] = false;
                set.pack();
                return;
            }
            oneId[0] = m.servo();
            oneModel[0] = m.model();
            bus.watchdog(oneId, oneModel, 1, profile.watchdogMs(), profile.onFault() == SafeMode.LIMP);
            report.note("bus: " + who(m) + " answers now; driving it");
            return;
        }
    }

    private int indexOfSlot(int n, int j) {
        for (int k = 0; k < n; k++) {
            if (set.slotOf(k) == j) {
                return k;
            }
        }
        throw new IllegalStateException("mapped servo " + j + " is not driven");
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
    protected String setUpAgain() throws IOException {
        setUp();
        armWatchdog();
        failedReads = 0;
        readAttempt = 0;
        java.util.Arrays.fill(backoff, 0);
        lastProbe = System.nanoTime();
        return "";
    }
}
