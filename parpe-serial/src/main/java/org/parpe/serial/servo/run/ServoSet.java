package org.parpe.serial.servo.run;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
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
    private final ServoMapping[] mappings;
    private final int[] runIndex;
    final boolean[] driven;
    private final int[] packed;
    final int[] ids;
    final ServoModel[] models;
    final int[] goals;
    final double[] degrees;
    final int[] errors;
    private final double[] joint;
    private final double[] measured;
    private final boolean[] have;
    private final boolean[] clampWarned;
    private final boolean[] faultShown;
    private boolean fresh;
    private boolean hasSetpoints;
    private long clamps;

    ServoSet(HardwareProfile profile, int[] runModules) {
        this.runModules = runModules.clone();
        List<ServoMapping> m = new ArrayList<>();
        List<Integer> idx = new ArrayList<>();
        for (int i = 0; i < runModules.length; i++) {
            ServoMapping s = profile.forModule(runModules[i]);
            if (s != null) {
                m.add(s);
                idx.add(i);
            }
        }
        int n = m.size();
        mappings = m.toArray(new ServoMapping[0]);
        runIndex = idx.stream().mapToInt(Integer::intValue).toArray();
        driven = new boolean[n];
        packed = new int[n];
        ids = new int[n];
        models = new ServoModel[n];
        goals = new int[n];
        degrees = new double[n];
        errors = new int[n];
        joint = new double[n];
        measured = new double[n];
        have = new boolean[n];
        clampWarned = new boolean[n];
        faultShown = new boolean[n];
    }

    /** Mapped servos. */
    int size() {
        return mappings.length;
    }

    ServoMapping mapping(int j) {
        return mappings[j];
    }

    /** Modules of the run without a servo in the profile. */
    List<Integer> unmapped() {
        List<Integer> out = new ArrayList<>();
        for (int i = 0, j = 0; i < runModules.length; i++) {
            if (j < runIndex.length && runIndex[j] == i) {
                j++;
            } else {
                out.add(runModules[i]);
            }
        }
        return out;
    }

    /** The mapping of the servo at packed index {@code k}. */
    ServoMapping mappingAt(int k) {
        return mappings[packed[k]];
    }

    /**
     * The goal that holds the servo at packed index {@code k} where it was last measured, clamped
     * into its limits (a servo resting beyond them is brought just inside).
     */
    synchronized int holdTicks(int k) {
        ServoMapping m = mappings[packed[k]];
        return m.goalTicks(m.clamp(measured[packed[k]]));
    }

    /** Packs the driven servos into {@link #ids} and {@link #models}; returns how many. */
    synchronized int pack() {
        int k = 0;
        for (int j = 0; j < mappings.length; j++) {
            if (driven[j]) {
                packed[k] = j;
                ids[k] = mappings[j].servo();
                models[k++] = mappings[j].model();
            }
        }
        return k;
    }

    /** One tick's setpoints (run order): clamped to each servo's limits, warned once per module. */
    synchronized void accept(long tick, double[] commanded, Consumer<String> warn) {
        for (int j = 0; j < mappings.length; j++) {
            double v = commanded[runIndex[j]];
            if (!Double.isFinite(v)) {
                continue;
            }
            ServoMapping m = mappings[j];
            double c = m.clamp(v);
            if (c != v) {
                clamps++;
                if (!clampWarned[j]) {
                    clampWarned[j] = true;
                    warn.accept(String.format(Locale.ROOT, "module %d commanded %.2f° at tick %d, outside its "
                            + "limits %.2f..%.2f° (%s); sending %.2f° (further clamps are counted)", m.module(), v, tick,
                            m.min(), m.max(), m.where(), c));
                }
            }
            joint[j] = c;
        }
        fresh = true;
        hasSetpoints = true;
        notifyAll();
    }

    /** Fills {@link #goals} (packed order) when new setpoints came or {@code keepalive} is set. */
    synchronized boolean takeGoals(boolean keepalive) {
        if (!hasSetpoints || !(fresh || keepalive)) {
            return false;
        }
        int n = pack();
        for (int k = 0; k < n; k++) {
            goals[k] = mappings[packed[k]].goalTicks(joint[packed[k]]);
        }
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
     * Stores what a position read left in {@link #degrees} and {@link #errors}; reports each servo
     * that starts or stops reporting a fault. Returns the number of new faults.
     */
    int storeReadings(int n, ServoBus bus, Consumer<String> report) throws IOException {
        int newFaults = 0;
        for (int k = 0; k < n; k++) {
            int j = packed[k];
            if (errors[k] == ServoBus.NO_REPLY) {
                continue;
            }
            synchronized (this) {
                measured[j] = mappings[j].jointAngle(degrees[k]);
                have[j] = true;
                if (!hasSetpoints) {
                    joint[j] = mappings[j].clamp(measured[j]);
                }
            }
            boolean faulty = bus.faulty(errors[k]);
            if (faulty && !faultShown[j]) {
                faultShown[j] = true;
                newFaults++;
                ServoMapping m = mappings[j];
                String what = bus.describeFault(m.servo(), m.model(), errors[k]);
                report.accept(String.format(Locale.ROOT, "servo %d (module %d) reports %s; it may have turned its "
                        + "torque off: let it cool down or remove the load, then power-cycle it", m.servo(), m.module(),
                        what == null ? String.format("error 0x%02X", errors[k]) : what));
            } else if (!faulty && faultShown[j]) {
                faultShown[j] = false;
                report.accept("servo " + mappings[j].servo() + " (module " + mappings[j].module() + ") reports no fault now");
            }
        }
        return newFaults;
    }

    /** Copies measured angles into {@code table}; a servo never read shows its setpoint. */
    synchronized void copyTo(SensorTable table, Channel angle) {
        for (int j = 0; j < mappings.length; j++) {
            if (have[j]) {
                table.set(runIndex[j], angle, measured[j]);
            } else if (hasSetpoints) {
                table.set(runIndex[j], angle, joint[j]);
            }
        }
    }

    /** The measured joint angle of run module {@code index}, NaN before any reading. */
    synchronized double measured(int index) {
        for (int j = 0; j < mappings.length; j++) {
            if (runIndex[j] == index) {
                return have[j] ? measured[j] : Double.NaN;
            }
        }
        return Double.NaN;
    }

    synchronized long clamps() {
        return clamps;
    }
}
