package org.parpe.core.export;

/**
 * What the servo driver of the board code adds to a program on a board, beyond the board's own
 * share ({@link Board#boardRam()}, {@link Board#runtimeFlash()}): its buffers and pin tables in
 * RAM, its code in flash, its time in each tick.
 *
 * @param ram    bytes of RAM
 * @param flash  bytes of flash
 * @param cycles CPU cycles of an AVR board per tick (sending the setpoints)
 */
public record DriverCost(long ram, long flash, long cycles) {
    /** No driver: the plain C export, whose board code is the user's. */
    public static final DriverCost NONE = new DriverCost(0, 0, 0);
}
