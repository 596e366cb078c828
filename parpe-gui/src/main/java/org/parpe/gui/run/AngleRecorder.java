package org.parpe.gui.run;

import java.util.Arrays;
import org.parpe.core.sensor.Channel;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.RunInfo;
import org.parpe.core.sensor.SensorTable;

/**
 * Records commanded and measured joint angles of every module for the live plots: an observer of
 * the commanded angles and of the readings for the measured ones.
 * Written on the engine thread (no allocation once started), read on the UI thread; a ring
 * of {@value #CAPACITY} samples taken at most every {@value #INTERVAL} s of simulated time.
 */
public final class AngleRecorder implements JointSink {
    static final int CAPACITY = 4096;
    static final double INTERVAL = 0.02;

    private int[] ids = new int[0];
    private double[] times = new double[CAPACITY];
    private double[] commanded = new double[0];
    private double[] measured = new double[0];
    private double[] latestMeasured = new double[0];
    private int modules;
    private long written;
    private double lastTime = Double.NEGATIVE_INFINITY;

    @Override
    public synchronized void start(RunInfo info) {
        ids = info.moduleIds().clone();
        modules = ids.length;
        commanded = new double[CAPACITY * modules];
        measured = new double[CAPACITY * modules];
        latestMeasured = new double[modules];
        Arrays.fill(latestMeasured, Double.NaN);
        written = 0;
        lastTime = Double.NEGATIVE_INFINITY;
    }

    /** Keeps the angle readings the scheduler uses this tick, for the plots (an observer of the readings). */
    public void keepMeasured(double time, SensorTable table) {
        int n = Math.min(latestMeasured.length, table.moduleCount());
        for (int i = 0; i < n; i++) {
            latestMeasured[i] = table.get(i, Channel.ANGLE);
        }
    }

    @Override
    public void accept(long tick, double time, double[] angles) {
        if (time < lastTime + INTERVAL - 1e-9) {
            return;
        }
        synchronized (this) {
            lastTime = time;
            int row = (int) (written % CAPACITY);
            times[row] = time;
            System.arraycopy(angles, 0, commanded, row * modules, Math.min(modules, angles.length));
            System.arraycopy(latestMeasured, 0, measured, row * modules, modules);
            written++;
        }
    }

    /** The recorded module IDs, ascending. */
    public synchronized int[] moduleIds() {
        return ids.clone();
    }

    /**
     * Copies the samples of module {@code id} into the arrays (oldest first) and returns how
     * many there are (0 for an unknown module). The arrays must hold {@link #capacity()} values.
     */
    public synchronized int copy(int id, double[] t, double[] cmd, double[] meas) {
        int m = Arrays.binarySearch(ids, id);
        if (m < 0) {
            return 0;
        }
        int count = (int) Math.min(written, CAPACITY);
        long first = written - count;
        for (int k = 0; k < count; k++) {
            int row = (int) ((first + k) % CAPACITY);
            t[k] = times[row];
            cmd[k] = commanded[row * modules + m];
            meas[k] = measured[row * modules + m];
        }
        return count;
    }

    /** The size the arrays given to {@link #copy} must have. */
    public static int capacity() {
        return CAPACITY;
    }
}
