package org.parpe.serial.servo.run;

import org.parpe.core.text.Message;
import org.parpe.serial.text.SerialMsg;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.BusReport;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ServoMapping;

/**
 * How {@link ServoDriver} finds the servos of a run and brings them into a safe hold before it
 * drives them, on every protocol: at discovery, again after a silence, and for a servo that
 * answers only later. A servo is driven only if it answers as the profile's model (or one with
 * the same control table and units), from the position it reports, clamped into its limits,
 * with its torque on and read back. Bus thread (or the run's set-up) only.
 */
final class ServoSetUp {
    private final ServoSet set;
    private final HardwareProfile profile;
    private final BusConfig config;
    private final BusReport report;
    /** Per mapped servo: answered as another model; never driven, never probed. */
    private final boolean[] otherModel;
    private final List<Integer> answeredOther = new ArrayList<>();
    private final List<Integer> limp = new ArrayList<>();
    private final int[] oneId = new int[1];
    private final ServoModel[] oneModel = new ServoModel[1];
    private final double[] oneDegrees = new double[1];
    private final int[] oneError = new int[1];
    private final int[] oneGoal = new int[1];

    ServoSetUp(ServoSet set, HardwareProfile profile, BusConfig config, BusReport report) {
        this.set = set;
        this.profile = profile;
        this.config = config;
        this.report = report;
        this.otherModel = new boolean[set.size()];
    }

    /** A servo in messages: {@code servo 3 (module 1)}, or {@code module 1} where they are one (G1 by ID). */
    static String who(ServoProtocol protocol, ServoMapping m) {
        return protocol.modules() && m.servo() == m.module() ? SerialMsg.WHO_MODULE.text(m.module())
                : SerialMsg.WHO_SERVO.text(m.servo(), m.module());
    }

    private String who(ServoMapping m) {
        return who(profile.protocol(), m);
    }

    /** See {@link ServoDriver#discover}. */
    List<Integer> discover(ServoBus bus) throws IOException {
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
            holdAll(bus);
        }
        return found;
    }

    /** Modules whose servo answered discovery as another model than the profile's, and is not driven. */
    List<Integer> answeredAsOtherModel() {
        return List.copyOf(answeredOther);
    }

    /** Modules whose servo answered but stayed limp (torque off, or its position unknown) after set-up. */
    List<Integer> limp() {
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
        report.problem("bus: " + SerialMsg.WRONG_MODEL.text(who(m), actual == null ? SerialMsg.UNKNOWN_MODEL.text(model)
                : SerialMsg.A_MODEL.text(actual.label()), m.model().label(), m.where(),
                (same ? SerialMsg.DRIVING_ANYWAY : SerialMsg.WILL_NOT_MOVE).text()));
        return same;
    }

    /**
     * Present positions (retried until each servo has answered), goals that hold each servo
     * there clamped into its limits, torque on, and torque read back: a servo whose torque does
     * not come on is limp while the run drives it, which the user must hear about.
     */
    void holdAll(ServoBus bus) throws IOException {
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
            if (!holdFound(bus, k, known[k], attempts)) {
                limp.add(set.mappingAt(k).module());
            }
        }
        // Not driven until it answers and holds: the missing-servo probe tries it again.
        for (int k = 0; k < n; k++) {
            if (limp.contains(set.mappingAt(k).module())) {
                set.driven[set.slotOf(k)] = false;
            }
        }
        set.pack();
    }

    /** After a silence: the driven servos held again; returns {@code 4 of 5 answer, missing 3}. */
    Message holdAgain(ServoBus bus) throws IOException {
        holdAll(bus);
        List<Integer> missing = new ArrayList<>();
        for (int j = 0; j < set.size(); j++) {
            if (missing(j)) {
                missing.add(set.mapping(j).module());
            }
        }
        int answer = set.size() - missing.size();
        return missing.isEmpty() ? Message.of(SerialMsg.ANSWER, answer, set.size())
                : Message.of(SerialMsg.ANSWER_MISSING, answer, set.size(), org.parpe.serial.bus.Discovery.format(missing));
    }

    /**
     * Packed servo {@code k}, its position {@code known} or not, is held there, torque on and read
     * back; false (reported) when its position is unknown or its torque did not come on.
     */
    private boolean holdFound(ServoBus bus, int k, boolean known, int attempts) throws IOException {
        ServoMapping m = set.mappingAt(k);
        if (!known) {
            report.problem("bus: " + SerialMsg.PING_BUT_NO_READS.text(who(m), attempts));
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
            report.problem("bus: " + SerialMsg.TORQUE_NOT_ON.text(who(m),
                    (state == 0 ? SerialMsg.READ_BACK_0 : SerialMsg.NOT_READ_BACK).text(), attempts));
        }
        return state == 1;
    }

    /** Whether mapped servo {@code j} is one to look for: not driven, and not known to be another model. */
    boolean missing(int j) {
        return !set.driven[j] && !otherModel[j];
    }

    /**
     * Pings mapped servo {@code j}, which did not answer before; one that answers as its model is
     * set up as at discovery (held where it is, torque on, its watchdog armed) and driven from
     * then on (said so). Returns −1 when it did not answer, 1 when it is driven now, 0 otherwise.
     */
    int bringIn(ServoBus bus, int j) throws IOException {
        ServoMapping m = set.mapping(j);
        int model = bus.ping(m.servo(), 1);
        if (model < 0) {
            return -1;
        }
        if (!compatible(m, model)) {
            otherModel[j] = true;
            return 0;
        }
        oneId[0] = m.servo();
        oneModel[0] = m.model();
        if (bus.readPositions(oneId, oneModel, 1, oneDegrees, oneError) == 0) {
            return 0;
        }
        set.driven[j] = true;
        int k = packedIndex(set.pack(), j);
        set.degrees[k] = oneDegrees[0];
        set.errors[k] = oneError[0];
        set.storeReadings(k, k + 1, bus, this::fault);
        if (!holdFound(bus, k, true, 2)) {
            set.driven[j] = false;
            set.pack();
            return 0;
        }
        oneId[0] = m.servo();
        oneModel[0] = m.model();
        bus.watchdog(oneId, oneModel, 1, profile.watchdogMs(), profile.onFault() == SafeMode.LIMP);
        report.note("bus: " + SerialMsg.ANSWERS_NOW.text(who(m)));
        return 1;
    }

    private int packedIndex(int n, int j) {
        for (int k = 0; k < n; k++) {
            if (set.slotOf(k) == j) {
                return k;
            }
        }
        throw new IllegalStateException("mapped servo " + j + " is not driven");
    }

    private void fault(String message) {
        report.problem("bus: " + message);
    }
}
