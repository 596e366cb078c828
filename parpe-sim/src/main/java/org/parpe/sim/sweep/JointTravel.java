package org.parpe.sim.sweep;

import org.parpe.core.sensor.Channel;
import org.parpe.core.run.SensorSource;
import org.parpe.core.sensor.SensorTable;

/**
 * The energy proxy of a run: the summed absolute change of every measured joint angle, tick to
 * tick. A tap on the readings; allocates nothing once the run has started.
 */
final class JointTravel implements SensorSource {
    private double[] last = new double[0];
    private boolean started;
    private double total;

    @Override
    public void read(double time, SensorTable table) {
        int n = table.moduleCount();
        if (!started) {
            last = new double[n];
            for (int i = 0; i < n; i++) {
                last[i] = table.get(i, Channel.ANGLE);
            }
            started = true;
            return;
        }
        for (int i = 0; i < n; i++) {
            double a = table.get(i, Channel.ANGLE);
            total += Math.abs(a - last[i]);
            last[i] = a;
        }
    }

    /** Degrees turned by all joints together. */
    double total() {
        return total;
    }
}
