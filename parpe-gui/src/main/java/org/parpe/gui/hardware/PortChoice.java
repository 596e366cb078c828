package org.parpe.gui.hardware;

/**
 * The serial port and hardware profile a run on the robot uses, as the Run tool bar shows them:
 * the Hardware dialog reads and sets them there, so a bus found in the dialog is the one Run uses.
 */
public interface PortChoice {
    /** The port typed or chosen, trimmed ("" for none). */
    String port();

    /** Shows {@code port} as the one to use. */
    void setPort(String port);

    /** The hardware profile chosen, or null for G1 modules without one. */
    String hardwareProfile();

    /** Shows the profile {@code file} as the one to use. */
    void setHardwareProfile(String file);
}
