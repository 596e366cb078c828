package org.parpe.gui.pose;

/**
 * The robot on the serial bus while posing, in joint angles of script modules (the hardware
 * profile's zero and direction applied). Calls return at once; the bus is driven on its own
 * thread. UI thread only.
 */
public interface PoseHardware {
    /** A name for messages ("3 servos on /dev/ttyUSB0"). */
    String describe();

    /** Torque off (limp: move the robot by hand) or on (hold where it is) for {@code modules}. */
    void limp(int[] modules, boolean limp);

    /**
     * The last angles read (polled a few times a second) for {@code modules}, degrees, in that
     * order; throws {@link IllegalStateException} naming a module that has no servo or no reading.
     */
    double[] angles(int[] modules);

    /** Sends module {@code id} to {@code degrees} (sync mode: the real robot follows the sliders). */
    void move(int id, double degrees);
}
