package org.parpe.core.run;

/**
 * What a sensor source and its measured trace columns come from: the key a target offers its
 * source under ({@link Run.Builder#sensorSource(SourceKind, SensorSource)}), the priority that
 * decides which source a run reads, and the name of its measured-angle trace column.
 */
public enum SourceKind {
    /** The simulator: read when no hardware is attached; measured angles in columns {@code a<ID>}. */
    SIMULATOR,
    /** The robot on a serial bus: read over the simulator; measured angles in columns {@code hw<ID>}. */
    HARDWARE;

    /** The higher of two offered sources is read, whatever the order of offering. */
    public int priority() {
        return switch (this) {
            case SIMULATOR -> 5;
            case HARDWARE -> 10;
        };
    }

    /** The trace column of module {@code id}'s measured angle from this source ({@code a3}, {@code hw3}). */
    public String column(int id) {
        String prefix = switch (this) {
            case SIMULATOR -> "a";
            case HARDWARE -> "hw";
        };
        return prefix + id;
    }
}
