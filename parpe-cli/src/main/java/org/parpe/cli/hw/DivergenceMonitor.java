package org.parpe.cli.hw;

import java.io.PrintStream;
import java.util.Locale;
import org.parpe.core.sensor.Channel;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.SensorSource;
import org.parpe.core.sensor.SensorTable;

/**
 * Compares the measured angles of the hardware and the simulator every tick (a sink added after
 * both) and reports where they differ by more than a threshold: once when a module starts to
 * diverge, once when it comes back (below 80 % of the threshold), and a summary at the end.
 */
final class DivergenceMonitor implements JointSink {
    private static final double HYSTERESIS = 0.8;
    private final SensorSource sim;
    private final java.util.function.IntToDoubleFunction hardware;
    private final double threshold;
    private final PrintStream err;
    private SensorTable simTable;
    private int[] ids;
    private boolean[] diverged;
    private double[] worst;
    private double[] worstTime;
    private long[] ticksDiverged;
    private double dt;

    DivergenceMonitor(SensorSource sim, java.util.function.IntToDoubleFunction hardware, double threshold, PrintStream err) {
        this.sim = sim;
        this.hardware = hardware;
        this.threshold = threshold;
        this.err = err;
    }

    @Override
    public void start(RunInfo info) {
        ids = info.moduleIds().clone();
        dt = info.dt();
        simTable = new SensorTable(ids);
        diverged = new boolean[ids.length];
        worst = new double[ids.length];
        worstTime = new double[ids.length];
        ticksDiverged = new long[ids.length];
    }

    @Override
    public void accept(long tick, double time, double[] commanded) {
        sim.read(time, simTable);
        for (int i = 0; i < ids.length; i++) {
            double hw = hardware.applyAsDouble(i);
            if (Double.isNaN(hw)) {
                continue;
            }
            double s = simTable.get(i, Channel.ANGLE);
            double d = Math.abs(hw - s);
            if (d > worst[i]) {
                worst[i] = d;
                worstTime[i] = time;
            }
            if (d > threshold) {
                ticksDiverged[i]++;
            }
            // Hysteresis: a module back within 80 % of the threshold, so noise at the edge does not chatter.
            boolean now = diverged[i] ? d > HYSTERESIS * threshold : d > threshold;
            if (now != diverged[i]) {
                diverged[i] = now;
                err.println(String.format(Locale.ROOT, now
                        ? "diverge: module %d at t=%.3f s: hardware %.2f°, simulator %.2f° (more than %.2f° apart)"
                        : "diverge: module %d back within threshold at t=%.3f s: hardware %.2f°, simulator %.2f° (threshold %.2f°)",
                        ids[i], time, hw, s, threshold));
            }
        }
    }

    @Override
    public void finish(RunOutcome outcome) {
        if (ids == null) {
            return;
        }
        int count = 0;
        for (int i = 0; i < ids.length; i++) {
            if (ticksDiverged[i] > 0) {
                count++;
                err.println(String.format(Locale.ROOT, "diverge: module %d was more than %.2f° off for %.2f s; "
                        + "worst %.2f° at t=%.3f s", ids[i], threshold, ticksDiverged[i] * dt, worst[i], worstTime[i]));
            }
        }
        if (count == 0) {
            err.println(String.format(Locale.ROOT, "diverge: hardware and simulator stayed within %.2f° "
                    + "(largest difference %.2f°)", threshold, java.util.Arrays.stream(worst).max().orElse(0)));
        }
    }
}
