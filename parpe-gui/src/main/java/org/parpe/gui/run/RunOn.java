package org.parpe.gui.run;

/** What a run drives. */
public enum RunOn {
    SIMULATOR("Simulator"),
    HARDWARE("Hardware"),
    BOTH("Simulator + hardware");

    private final String label;

    RunOn(String label) {
        this.label = label;
    }

    public String label() {
        return label;
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
