package org.parpe.core.run;

import org.parpe.core.sensor.SensorTable;

/**
 * Supplies measured sensor readings (simulator, hardware). Called once per tick, at step 1
 * of PARSL.md §11, after the plant has reached {@code time}. Without a source, {@code angle}
 * reads the commanded angle of the previous tick and {@code accel}/{@code touch} read 0.
 * Stimulus overrides are applied by the scheduler after this call.
 */
@FunctionalInterface
public interface SensorSource {

    /**
     * Writes the readings for {@code time} into {@code table}. Channels the source does not
     * measure may be left as they are; before the first call every reading is 0 except
     * {@code angle}, which holds the commanded angle.
     */
    void read(double time, SensorTable table);
}
