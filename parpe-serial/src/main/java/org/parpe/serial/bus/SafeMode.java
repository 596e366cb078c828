package org.parpe.serial.bus;

/** What a module does when it stops on its own (watchdog, emergency stop). */
public enum SafeMode {
    /** Keep the current angle with the servo on. */
    HOLD(0),
    /** Turn the servo off: the joint goes slack. */
    LIMP(1);

    private final int wire;

    SafeMode(int wire) {
        this.wire = wire;
    }

    /** The protocol's code for this mode. */
    public int wire() {
        return wire;
    }
}
