package org.parpe.core.run;

/**
 * One line of a stimulus file: at {@code time}, set a control or override a sensor reading.
 *
 * @param time   seconds
 * @param line   the line in the stimulus file
 * @param target what is set
 * @param index  the control index, or the sensor-table slot
 * @param value  the value (a radio word's symbol code for radio controls)
 * @param text   the assignment as written, for messages
 */
public record Stimulus(double time, int line, Kind target, int index, double value, String text) {

    /** What a stimulus sets. */
    public enum Kind { CONTROL, SENSOR }
}
