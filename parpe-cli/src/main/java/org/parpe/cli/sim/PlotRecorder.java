package org.parpe.cli.sim;

import java.util.Arrays;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.SourceKind;
import org.parpe.core.run.TraceColumns;
import org.parpe.sim.Simulator;

/**
 * Keeps commanded and measured angles for {@code --plot}: an observer of the run, so it sees
 * each tick after the simulator, whose trace columns then hold the measured angles of the same
 * tick. Samples at most about {@value #TARGET_SAMPLES} ticks of a run of known length; grows its arrays otherwise.
 */
final class PlotRecorder implements JointSink {
    private static final int TARGET_SAMPLES = 4000;

    private final int[] ids;
    private final int[] measuredColumn;
    private final TraceColumns columns;
    private double[] row = new double[0];
    private final long stride;
    private double dt = 0.01;
    private double[] times = new double[1024];
    private double[] commanded;
    private double[] measured;
    private int count;

    PlotRecorder(Simulator sim, int[] moduleIds, double duration, double tick) {
        ids = moduleIds.clone();
        columns = sim.traceColumns();
        measuredColumn = new int[ids.length];
        commanded = new double[times.length * ids.length];
        measured = new double[times.length * ids.length];
        stride = Double.isFinite(duration) ? Math.max(1, (long) (duration / tick) / TARGET_SAMPLES) : 1;
    }

    /** Finds the measured columns: the simulator, a plant, has bound the program's modules by now. */
    @Override
    public void start(org.parpe.core.run.RunInfo info) {
        dt = info.dt();
        String[] names = columns.names();
        row = new double[names.length];
        for (int i = 0; i < ids.length; i++) {
            measuredColumn[i] = Arrays.asList(names).indexOf(SourceKind.SIMULATOR.column(ids[i]));
        }
    }

    @Override
    public void accept(long tick, double time, double[] cmd) {
        if (tick % stride != 0) {
            return;
        }
        if (count == times.length) {
            times = Arrays.copyOf(times, count * 2);
            commanded = Arrays.copyOf(commanded, count * 2 * ids.length);
            measured = Arrays.copyOf(measured, count * 2 * ids.length);
        }
        columns.values(row);
        times[count] = time;
        for (int i = 0; i < ids.length; i++) {
            commanded[count * ids.length + i] = cmd[i];
            measured[count * ids.length + i] = measuredColumn[i] >= 0 ? row[measuredColumn[i]] : Double.NaN;
        }
        count++;
    }

    int moduleCount() {
        return ids.length;
    }

    int id(int module) {
        return ids[module];
    }

    int samples() {
        return count;
    }

    double time(int sample) {
        return times[sample];
    }

    double commanded(int sample, int module) {
        return commanded[sample * ids.length + module];
    }

    double measured(int sample, int module) {
        return measured[sample * ids.length + module];
    }

    double dt() {
        return dt;
    }
}
