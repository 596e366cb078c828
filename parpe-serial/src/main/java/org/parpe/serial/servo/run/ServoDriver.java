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
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ServoMapping;

/**
 * Drives the servos of a hardware profile from a run. The engine's setpoints are clamped to each
 * servo's limits (warned once per module, counted always) and turned into goal ticks; a bus
 * thread sends them in one packet, repeats them as a keepalive, and reads present positions,
 * which become the modules' measured angles: every servo each read cycle where the protocol has a
 * group read, one servo per read cycle, round robin, where it has none (G1). A servo reporting a fault (overload, overheating,
 * voltage) is reported in words. When every servo falls silent or the device goes away, the
 * driver reports it at once, keeps looking and resumes when they are back.
 */
public final class ServoDriver extends BusThread {
    private static final int READ_EVERY_WHEN_BUSY = 10;
    private static final int READ_GAP_MS = 2;
    private static final int WATCHDOG_CHECK_MS = 100;

    private final LinkOpener opener;
    private final HardwareProfile profile;
    private volatile ServoBus bus;
    private final ServoSet set;
    private long lastSend;
    private int failedReads;
    private int busyCycles;
    private long reads;
    private long readFailures;
    private long faults;
    private long watchdogResumes;
    private long lastWatchdogCheck;
    private int watchdogCursor;
    /** Reads one servo per read cycle (the protocol has no group read), this one next. */
    private final boolean roundRobin;
    private int readCursor;
    private final int[] oneId = new int[1];
    private final ServoModel[] oneModel = new ServoModel[1];
    private final double[] oneDegrees = new double[1];
    private final int[] oneError = new int[1];
    private final List<Integer> answeredOther = new ArrayList<>();
    private final List<Integer> limp = new ArrayList<>();

    private ServoDriver(LinkOpener opener, ServoBus bus, BusConfig config, HardwareProfile profile, int[] runModules,
                        BusReport report) {
        super(config, report, "servo");
        this.opener = opener;
        this.bus = bus;
        this.profile = profile;
        this.set = new ServoSet(profile, runModules);
        this.roundRobin = !profile.protocol().groupRead();
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
        report.problem(String.format(Locale.ROOT, "bus: servo %d (module %d) is %s, the profile says %s at %s; %s",
                m.servo(), m.module(), actual == null ? "of unknown model " + model : "an " + actual.label(),
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
        int[] one = new int[1];
        ServoModel[] oneModel = new ServoModel[1];
        int[] oneGoal = new int[1];
        for (int k = 0; k < n; k++) {
            ServoMapping m = set.mappingAt(k);
            if (!known[k]) {
                limp.add(m.module());
                report.problem(String.format(Locale.ROOT, "bus: servo %d (module %d) answered the ping but not %d "
                        + "reads of its position; its torque stays off and it will not follow the run", m.servo(),
                        m.module(), attempts));
                continue;
            }
            one[0] = m.servo();
            oneModel[0] = m.model();
            oneGoal[0] = set.holdTicks(k);
            int state = 0;
            for (int a = 0; a < attempts && state != 1; a++) {
                bus.holdAt(one, oneModel, oneGoal, 1);
                state = bus.torqueState(m.servo(), m.model(), 2);
            }
            if (state != 1) {
                limp.add(m.module());
                report.problem(String.format(Locale.ROOT, "bus: servo %d (module %d) did not turn its torque on "
                        + "(Torque Enable %s after %d tries); it is limp and will not follow the run", m.servo(),
                        m.module(), state == 0 ? "read back 0" : "could not be read back", attempts));
            }
        }
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
        set.copyTo(table, Channel.ANGLE);
    }

    /** The last measured joint angle of run module {@code index}, NaN before any. */
    public double measuredAngle(int index) {
        return set.measured(index);
    }

    /** Turns the watchdog off so the servos keep holding, sends the last goals (three times: no reply). */
    @Override
    protected void sendFinalHold() throws IOException {
        int n = set.pack();
        // Watchdog off first: writing 0 also clears a Bus Watchdog error, which a pause at
        // the run's end may have caused and which would refuse the final goals.
        bus.watchdog(set.ids, set.models, n, 0, false);
        for (int i = 0; i < 3 && set.takeGoals(true); i++) {
            bus.writeGoals(set.ids, set.models, set.goals, n);
        }
    }

    @Override
    protected IOException linkError() {
        return bus.linkError();
    }

    /** Every driven servo stops in the profile's safe mode. */
    @Override
    protected String sendEmergencyStop() throws IOException {
        boolean limp = profile.onFault() == SafeMode.LIMP;
        bus.emergencyStop(set.ids, set.models, set.pack(), limp);
        return "servos " + (limp ? "limp (torque off)" : "hold where they are");
    }

    @Override
    public String summary() {
        ServoBus.Counters c = bus.counters();
        return String.format(Locale.ROOT, "bus %s (%s): %d packets sent, %d position reads (%d servo timeouts, "
                + "%d failed), %d bad checksums received, %d setpoints clamped, %d servo faults, %d watchdog stops, "
                + "%d disconnects", bus.name(), profile.protocol().key(), c.packetsSent(), reads, c.timeouts(),
                readFailures, c.checksumErrors(), set.clamps(), faults, watchdogResumes, disconnects());
    }

    /** Goals when new or due as keepalive, then a read of every servo unless goals saturate the line. */
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
            if (!read) {
                bus.writeGoals(set.ids, set.models, set.goals, n);
            }
        }
        if (read) {
            if (roundRobin && sent) {
                bus.writeGoals(set.ids, set.models, set.goals, n);
            }
            int answered = roundRobin ? readNext(n)
                    : sent ? bus.writeGoalsAndRead(set.ids, set.models, set.goals, n, set.degrees, set.errors)
                    : bus.readPositions(set.ids, set.models, n, set.degrees, set.errors);
            reads++;
            if (answered > 0) {
                answeredNow();
                failedReads = 0;
                if (!roundRobin) {
                    faults += set.storeReadings(0, n, bus, this::fault);
                    checkWatchdog(n);
                }
            } else if (n > 0) {
                readFailures++;
                // Dead: no answer for the dead-bus time and more failed reads in a row than retries.
                if (++failedReads > config.retries() && deadFor()) {
                    silent(bus.name(), safeStop());
                    return;
                }
            }
            if (!sent) {
                set.awaitFresh(READ_GAP_MS);
            }
        } else if (!sent) {
            set.awaitFresh(config.keepaliveMs());
        }
    }

    /**
     * Reads the present position of the next servo, round robin, and stores it; a servo whose
     * reply says it stopped on its own watchdog is resumed at once. Returns 1 when it answered.
     */
    private int readNext(int n) throws IOException {
        if (n == 0) {
            return 0;
        }
        int k = readCursor = (readCursor + 1) % n;
        oneId[0] = set.ids[k];
        oneModel[0] = set.models[k];
        int answered = bus.readPositions(oneId, oneModel, 1, oneDegrees, oneError);
        set.errors[k] = oneError[0];
        if (answered > 0) {
            set.degrees[k] = oneDegrees[0];
            faults += set.storeReadings(k, k + 1, bus, this::fault);
            resumeIfTripped(k);
        }
        return answered;
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

    /** What the servos do when the host loses them, and the torque-off attempt for limp. */
    private String safeStop() {
        if (profile.onFault() == SafeMode.LIMP) {
            try {
                bus.torque(set.ids, set.models, set.pack(), false);
            } catch (IOException e) {
                return "servos keep their last goal (the torque-off could not be sent)";
            }
            return "torque-off sent (limp)";
        }
        return "servos hold their last goal";
    }


    @Override
    protected String whileLost() {
        return "servos hold their last goal" + (profile.watchdogMs() > 0 ? " or stop on their own watchdog" : "");
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
        return "";
    }
}
