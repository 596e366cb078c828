package org.parpe.serial.servo.run;

import org.parpe.core.text.Message;
import org.parpe.serial.text.SerialMsg;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ServoMapping;

/**
 * The servos of one run and the hand-over between the engine thread and the bus thread: the
 * newest joint setpoints (clamped to the profile's limits) and the newest measured joint angles.
 * {@link #ids}, {@link #models}, {@link #goals}, {@link #degrees} and {@link #errors} are indexed
 * by the packed order of the driven servos ({@link #pack}) and belong to the bus thread. Nothing
 * allocates once a run has started.
 */
final class ServoSet {
    private final int[] runModules;
    /** The mapped servos in run order. */
    private final Slot[] slots;
    final boolean[] driven;
    private final int[] packed;
    final int[] ids;
    final ServoModel[] models;
    final int[] goals;
    final double[] degrees;
    final int[] errors;
    private boolean fresh;
    private boolean hasSetpoints;
    private long clamps;
    /** The run's tick of the newest setpoints (mod 2¹⁶), for protocols whose goals carry one. */
    private int seq;
    private int goalSeq;
    /** Where {@link ServoBus#sensors} leaves a servo's other sensors, bus thread only. */
    private final double[] sensed = new double[Slot.SENSORS];

    ServoSet(HardwareProfile profile, int[] runModules) {
        this.runModules = runModules.clone();
        List<Slot> found = new ArrayList<>();
        for (int i = 0; i < runModules.length; i++) {
            ServoMapping s = profile.forModule(runModules[i]);
            if (s != null) {
                found.add(new Slot(s, i));
            }
        }
        slots = found.toArray(new Slot[0]);
        int n = slots.length;
        driven = new boolean[n];
        packed = new int[n];
        ids = new int[n];
        models = new ServoModel[n];
        goals = new int[n];
        degrees = new double[n];
        errors = new int[n];
    }

    /** Mapped servos. */
    int size() {
        return slots.length;
    }

    ServoMapping mapping(int j) {
        return slots[j].mapping;
    }

    /** Modules of the run without a servo in the profile. */
    List<Integer> unmapped() {
        List<Integer> out = new ArrayList<>();
        for (int i = 0, j = 0; i < runModules.length; i++) {
            if (j < slots.length && slots[j].runIndex == i) {
                j++;
            } else {
                out.add(runModules[i]);
            }
        }
        return out;
    }

    /** The mapping of the servo at packed index {@code k}. */
    ServoMapping mappingAt(int k) {
        return slots[packed[k]].mapping;
    }

    /**
     * The goal that holds the servo at packed index {@code k} where it was last measured, clamped
     * into its limits (a servo resting beyond them is brought just inside).
     */
    synchronized int holdTicks(int k) {
        Slot s = slots[packed[k]];
        return s.mapping.goalTicks(s.mapping.clamp(s.measured));
    }

    /** Packs the driven servos into {@link #ids} and {@link #models}; returns how many. */
    synchronized int pack() {
        int k = 0;
        for (int j = 0; j < slots.length; j++) {
            if (driven[j]) {
                packed[k] = j;
                ids[k] = slots[j].mapping.servo();
                models[k++] = slots[j].mapping.model();
            }
        }
        return k;
    }

    /** One tick's setpoints (run order): clamped to each servo's limits, warned once per module. */
    synchronized void accept(long tick, double[] commanded, Consumer<String> warn) {
        for (int j = 0; j < slots.length; j++) {
            Slot s = slots[j];
            double v = commanded[s.runIndex];
            if (!Double.isFinite(v)) {
                continue;
            }
            ServoMapping m = s.mapping;
            double c = m.clamp(v);
            if (c != v) {
                clamps++;
                if (!s.clampWarned) {
                    s.clampWarned = true;
                    warn.accept(clamped(m, v, tick, c));
                }
            }
            s.joint = c;
        }
        seq = (int) (tick & 0xFFFF);
        fresh = true;
        hasSetpoints = true;
        notifyAll();
    }

    /**
     * The warning for a clamped setpoint: limits from a profile name its {@code <servo>}; the
     * joint range of modules driven without one (G1 with {@code --port}) is named as such.
     */
    private static String clamped(ServoMapping m, double v, long tick, double c) {
        if ((m.where() == null || m.where() == SourcePos.NONE) && m.min() == -m.max()) {
            return SerialMsg.CLAMPED_JOINT_RANGE.text(m.module(), f2(v), tick, String.format(Locale.ROOT, "%.0f", m.max()),
                    String.format(Locale.ROOT, "%.0f", c));
        }
        return SerialMsg.CLAMPED_LIMITS.text(m.module(), f2(v), tick, f2(m.min()), f2(m.max()), m.where(), f2(c));
    }

    /** A number with two decimals and a point, as the scripts write them. */
    private static String f2(double v) {
        return String.format(Locale.ROOT, "%.2f", v);
    }

    /** The run's tick of the goals {@link #takeGoals} took last, mod 2¹⁶ (bus thread). */
    int goalSeq() {
        return goalSeq;
    }

    /** The mapped servo (index into the mappings) at packed index {@code k}. */
    int slotOf(int k) {
        return packed[k];
    }

    /** Fills {@link #goals} (packed order) when new setpoints came or {@code keepalive} is set. */
    synchronized boolean takeGoals(boolean keepalive) {
        if (!hasSetpoints || !(fresh || keepalive)) {
            return false;
        }
        int n = pack();
        for (int k = 0; k < n; k++) {
            Slot s = slots[packed[k]];
            goals[k] = s.mapping.goalTicks(s.joint);
        }
        goalSeq = seq;
        fresh = false;
        return true;
    }

    /** Waits up to {@code millis} for new setpoints. */
    synchronized void awaitFresh(long millis) throws InterruptedException {
        if (!fresh) {
            wait(millis);
        }
    }

    /**
     * Stores what a position read of packed servos {@code from…to)} left in {@link #degrees} and
     * {@link #errors}; reports each servo that starts or stops reporting a fault. Returns the
     * number of new faults.
     */
    int storeReadings(int from, int to, ServoBus bus, Consumer<String> report) throws IOException {
        int newFaults = 0;
        for (int k = from; k < to; k++) {
            Slot s = slots[packed[k]];
            if (errors[k] == ServoBus.NO_REPLY) {
                continue;
            }
            boolean more = bus.sensors(ids[k], sensed);
            synchronized (this) {
                s.measured = s.mapping.jointAngle(degrees[k]);
                s.have = true;
                if (more) {
                    System.arraycopy(sensed, 0, s.sensors, 0, Slot.SENSORS);
                    s.hasSensors = true;
                }
                if (!hasSetpoints) {
                    s.joint = s.mapping.clamp(s.measured);
                }
            }
            boolean faulty = bus.faulty(errors[k]);
            if (faulty && !s.faultShown) {
                s.faultShown = true;
                newFaults++;
                ServoMapping m = s.mapping;
                String what = bus.describeFault(m.servo(), m.model(), errors[k]);
                report.accept(SerialMsg.FAULT.text(Message.of(SerialMsg.WHO_SERVO, m.servo(), m.module()),
                        what == null ? String.format("error 0x%02X", errors[k]) : what));
            } else if (!faulty && s.faultShown) {
                s.faultShown = false;
                report.accept(SerialMsg.NO_FAULT_NOW.text(Message.of(SerialMsg.WHO_SERVO, s.mapping.servo(), s.mapping.module())));
            }
        }
        return newFaults;
    }

    /**
     * Copies measured angles, and the other sensors where the devices have them, into
     * {@code table}; a servo never read shows its setpoint.
     */
    synchronized void copyTo(SensorTable table) {
        for (Slot s : slots) {
            if (s.have) {
                table.set(s.runIndex, Channel.ANGLE, s.measured);
            } else if (hasSetpoints) {
                table.set(s.runIndex, Channel.ANGLE, s.joint);
            }
            if (s.hasSensors) {
                for (int c = 0; c < Slot.SENSORS; c++) {
                    table.set(s.runIndex, Slot.CHANNELS[c], s.sensors[c]);
                }
            }
        }
    }

    /** The measured joint angle of run module {@code index}, NaN before any reading. */
    synchronized double measured(int index) {
        for (Slot s : slots) {
            if (s.runIndex == index) {
                return s.have ? s.measured : Double.NaN;
            }
        }
        return Double.NaN;
    }

    synchronized long clamps() {
        return clamps;
    }

    /** One mapped servo: its mapping, its place in the run and what the two threads handed over for it. */
    private static final class Slot {
        /** The sensors {@link ServoBus#sensors} reports, in its order. */
        static final Channel[] CHANNELS = {Channel.ACCEL_X, Channel.ACCEL_Y, Channel.ACCEL_Z, Channel.TOUCH_LEFT,
            Channel.TOUCH_RIGHT};
        static final int SENSORS = CHANNELS.length;
        final ServoMapping mapping;
        /** Index of its module in the run. */
        final int runIndex;
        /** The newest setpoint, clamped into the mapping's limits. */
        double joint;
        /** The newest measured joint angle, valid once {@link #have} is set. */
        double measured;
        boolean have;
        /** Whether a clamped setpoint was reported (once per module). */
        boolean clampWarned;
        /** Whether the servo's current fault was reported. */
        boolean faultShown;
        /** The other sensors of the last reading, valid once {@link #hasSensors} is set. */
        final double[] sensors = new double[SENSORS];
        boolean hasSensors;

        Slot(ServoMapping mapping, int runIndex) {
            this.mapping = mapping;
            this.runIndex = runIndex;
        }
    }
}
