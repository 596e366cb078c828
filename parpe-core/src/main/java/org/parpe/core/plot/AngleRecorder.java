package org.parpe.core.plot;

import java.util.Arrays;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunInfo;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;

/**
 * The one recorder of joint angles for every plot (the command line's {@code --plot} and the
 * IDE's live plot): per module, the <em>commanded</em> angle of each tick and the
 * <em>measured</em> angle, which is the angle reading of the run's sensor source for the same
 * tick (the simulator's joint angle, a servo's reported position), taken before any stimulus
 * overrides it: what the robot did, at the time the command was given. Without a sensor source
 * there is nothing measured (NaN).
 * <p>
 * Written on the engine thread without allocating once started; read from any thread. Holds at
 * most {@code capacity} samples: a {@linkplain #latest window} keeps the newest ones (the IDE's
 * scrolling plot), a {@linkplain #wholeRun whole run} keeps every tick until full and then every
 * second sample of those kept, doubling its interval, so the whole run stays (the PNG).
 */
public final class AngleRecorder implements JointSink {
    private final int capacity;
    private final boolean keepWholeRun;
    private double interval;
    private int[] ids = new int[0];
    private final double[] times;
    private double[] commanded = new double[0];
    private double[] measured = new double[0];
    private double[] reading = new double[0];
    private boolean hasReading;
    private int modules;
    private long written;
    private double lastTime;

    private AngleRecorder(int capacity, double interval, boolean keepWholeRun) {
        if (capacity < 2) {
            throw new IllegalArgumentException("capacity must be at least 2, got " + capacity);
        }
        this.capacity = capacity;
        this.interval = interval;
        this.keepWholeRun = keepWholeRun;
        this.times = new double[capacity];
    }

    /** Keeps the newest {@code capacity} samples, one at most every {@code interval} s of run time. */
    public static AngleRecorder latest(int capacity, double interval) {
        return new AngleRecorder(capacity, interval, false);
    }

    /** Keeps the whole run in at most {@code capacity} samples, evenly spaced. */
    public static AngleRecorder wholeRun(int capacity) {
        return new AngleRecorder(capacity, 0, true);
    }

    /** Records {@code run}: observes its commanded angles and the readings of its sensor source. */
    public AngleRecorder attachTo(Run.Builder run) {
        run.observer(this);
        run.observeReadings(this::keepReading);
        return this;
    }

    @Override
    public synchronized void start(RunInfo info) {
        ids = info.moduleIds().clone();
        modules = ids.length;
        commanded = new double[capacity * modules];
        measured = new double[capacity * modules];
        reading = new double[modules];
        hasReading = false;
        written = 0;
        lastTime = Double.NEGATIVE_INFINITY;
    }

    /** The angle readings of this tick, from the sensor source (step 1 of the tick, before the commands). */
    private void keepReading(double time, SensorTable table) {
        int n = Math.min(reading.length, table.moduleCount());
        for (int i = 0; i < n; i++) {
            reading[i] = table.get(i, Channel.ANGLE);
        }
        hasReading = true;
    }

    @Override
    public void accept(long tick, double time, double[] angles) {
        if (time < lastTime + interval - 1e-9) {
            hasReading = false;
            return;
        }
        synchronized (this) {
            if (keepWholeRun && written == capacity) {
                halve();
                if (time < lastTime + interval - 1e-9) {
                    hasReading = false;
                    return;
                }
            }
            lastTime = time;
            int row = (int) (written % capacity);
            times[row] = time;
            System.arraycopy(angles, 0, commanded, row * modules, Math.min(modules, angles.length));
            for (int i = 0; i < modules; i++) {
                measured[row * modules + i] = hasReading ? reading[i] : Double.NaN;
            }
            written++;
        }
        hasReading = false;
    }

    /** Keeps every second sample (the first, third, …) and doubles the interval. */
    private void halve() {
        int kept = 0;
        for (int s = 0; s < capacity; s += 2, kept++) {
            times[kept] = times[s];
            System.arraycopy(commanded, s * modules, commanded, kept * modules, modules);
            System.arraycopy(measured, s * modules, measured, kept * modules, modules);
        }
        written = kept;
        lastTime = times[kept - 1];
        double spacing = kept > 1 ? (times[kept - 1] - times[0]) / (kept - 1) : interval;
        interval = Math.max(2 * interval, spacing);
    }

    /** The recorded module IDs, ascending. */
    public synchronized int[] moduleIds() {
        return ids.clone();
    }

    /** How many samples there are now. */
    public synchronized int samples() {
        return (int) Math.min(written, capacity);
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
        int count = (int) Math.min(written, capacity);
        long first = written - count;
        for (int k = 0; k < count; k++) {
            int row = (int) ((first + k) % capacity);
            t[k] = times[row];
            cmd[k] = commanded[row * modules + m];
            meas[k] = measured[row * modules + m];
        }
        return count;
    }

    /** The size the arrays given to {@link #copy} must have. */
    public int capacity() {
        return capacity;
    }
}
