package org.parpe.serial.emu;

/** Observes what an emulator receives and does (tests, the {@code emulate} command's log). */
public interface EmulatorListener {

    /**
     * A SETPOINTS frame reached the modules: {@code seq}, and for each emulated module (in the
     * order of {@link org.parpe.serial.g1.emu.BusEmulator#moduleIds()}) the commanded angle, or NaN when the frame left
     * it unchanged. The array is reused.
     */
    default void onSetpoints(int seq, double[] angles) {
    }

    /** A module stopped on its own: {@code why} is "watchdog" or "emergency stop". */
    default void onSafeStop(int id, long nanoTime, String why) {
    }

    /** A line worth telling the user (unplugged, plugged back, port lost). */
    default void onEvent(String message) {
    }
}
