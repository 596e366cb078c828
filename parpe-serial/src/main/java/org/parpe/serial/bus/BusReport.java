package org.parpe.serial.bus;

import java.util.function.Consumer;

/**
 * Where a bus driver ({@link BusThread}) tells the user what happens on the bus, from any thread:
 * problems (faults, clamped setpoints, modules not answering) and notes (recoveries, the
 * emergency stop, the counters at the end). Messages start with {@code "bus: "} or
 * {@code "bus PORT: "}.
 */
public interface BusReport {

    /** Something went wrong or needs the user's attention. */
    void problem(String message);

    /** Something the user may want to know; not a problem. */
    void note(String message);

    /** Both kinds of message to one consumer, in order (logs, tests). */
    static BusReport lines(Consumer<String> out) {
        return new BusReport() {
            @Override
            public void problem(String message) {
                out.accept(message);
            }

            @Override
            public void note(String message) {
                out.accept(message);
            }
        };
    }
}
