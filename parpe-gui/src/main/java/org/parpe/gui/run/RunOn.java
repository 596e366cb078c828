package org.parpe.gui.run;

import org.parpe.core.text.Key;
import org.parpe.gui.text.UiMsg;

/** What a run drives. */
public enum RunOn {
    SIMULATOR(UiMsg.RUN_ON_SIMULATOR),
    HARDWARE(UiMsg.RUN_ON_HARDWARE),
    BOTH(UiMsg.RUN_ON_BOTH);

    private final Key label;

    RunOn(Key label) {
        this.label = label;
    }

    public String label() {
        return label.text();
    }

    /** Whether the simulator takes part: in every run but one on the hardware alone. */
    public boolean sim() {
        return this != HARDWARE;
    }

    /** Whether the robot on the serial bus takes part: in every run but one in the simulator alone. */
    public boolean hardware() {
        return this != SIMULATOR;
    }
}
