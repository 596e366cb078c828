package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
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
                err.println("diverge: " + (now ? CliMsg.DIVERGED : CliMsg.CONVERGED).text(ids[i], f("%.3f", time), f("%.2f", hw),
                        f("%.2f", s), f("%.2f", threshold)));
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
                err.println("diverge: " + CliMsg.DIVERGED_FOR.text(ids[i], f("%.2f", threshold), f("%.2f", ticksDiverged[i] * dt),
                        f("%.2f", worst[i]), f("%.3f", worstTime[i])));
            }
        }
        if (count == 0) {
            err.println("diverge: " + CliMsg.STAYED_WITHIN.text(f("%.2f", threshold),
                    f("%.2f", java.util.Arrays.stream(worst).max().orElse(0))));
        }
    }

    /** A number as the messages show it: a point for the decimals in every language. */
    private static String f(String format, double v) {
        return String.format(Locale.ROOT, format, v);
    }
}
