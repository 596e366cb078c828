package org.parpe.core.expr;

import java.util.SplittableRandom;
import org.parpe.core.sensor.SensorTable;

/**
 * The mutable values compiled expressions read: clock, controls, macros, sensors and the
 * current module. The scheduler owns one context per run and updates its fields in place, so
 * evaluation never allocates. Not thread-safe: confined to the engine thread.
 */
public final class EvalContext {
    /** Seconds since the program started. */
    public double time;
    /** Seconds since the current main entry started. */
    public double btime;
    /** Current control values by control index. */
    public double[] controls = new double[0];
    /** Macro values of the behavior being evaluated. */
    public double[] macros = new double[0];
    /** Sensor readings of this tick. */
    public SensorTable sensors;
    /** Position of the current module in its group. */
    public int index;
    /** Size of the current group. */
    public int count;
    /** Logical ID of the current module. */
    public int id;
    /** Cycle position u of the current module. */
    public double phase;
    /** Whole cycles the current module has completed. */
    public double cycle;
    /** Module indices (into the sensor table) of the current group, in group order. */
    public int[] group = new int[0];
    /** The run's random numbers, seeded by {@code --seed}. */
    public SplittableRandom random = new SplittableRandom(0);
}
