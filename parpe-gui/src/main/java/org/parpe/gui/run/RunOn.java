package org.parpe.gui.run;

/** What a run drives. */
public enum RunOn {
    SIMULATOR("Simulator", true, false),
    HARDWARE("Hardware", false, true),
    BOTH("Simulator + hardware", true, true);

    private final String label;
    private final boolean sim;
    private final boolean hardware;

    RunOn(String label, boolean sim, boolean hardware) {
        this.label = label;
        this.sim = sim;
        this.hardware = hardware;
    }

    public String label() {
        return label;
    }

    /** Whether the simulator takes part. */
    public boolean sim() {
        return sim;
    }

    /** Whether the robot on the serial bus takes part. */
    public boolean hardware() {
        return hardware;
    }
}
