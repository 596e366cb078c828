package org.parpe.core.run;

/**
 * What a sensor source and its measured trace columns come from: the key a target offers its
 * source under ({@link Run.Builder#sensorSource(SourceKind, SensorSource)}), the priority that
 * decides which source a run reads, and the name of its measured-angle trace column.
 */
public enum SourceKind {
    /** The simulator: read when no hardware is attached; measured angles in columns {@code a<ID>}. */
    SIMULATOR(5, "a"),
    /** The robot on a serial bus: read over the simulator; measured angles in columns {@code hw<ID>}. */
    HARDWARE(10, "hw");

    private final int priority;
    private final String columnPrefix;

    SourceKind(int priority, String columnPrefix) {
        this.priority = priority;
        this.columnPrefix = columnPrefix;
    }

    /** The higher of two offered sources is read, whatever the order of offering. */
    public int priority() {
        return priority;
    }

    /** The trace column of module {@code id}'s measured angle from this source ({@code a3}, {@code hw3}). */
    public String column(int id) {
        return columnPrefix + id;
    }
}
