package org.parpe.gui.hardware;

import java.nio.file.Path;
import java.util.List;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Shell;

/**
 * What the Hardware dialog needs of the window that owns it: the tool bar's port and profile, the
 * status bar's hardware field, the Pose panel (told when the bus is gone, and kept in view), the open
 * files (a profile is never saved over one), and the one dialog per window.
 */
public interface HardwareHost {
    Shell shell();

    /** The tool bar's port and profile. */
    PortChoice portChoice();

    /** What the status bar says while the dialog holds a bus; null when it holds none. */
    void setHardwareHeld(String state);

    /** The bus is gone: the Pose panel stops using the robot. */
    void hardwareGone();

    /** The Pose panel's control, which the dialog is placed so as not to cover. */
    Control posePanel();

    List<Path> openFiles();

    /** The open Hardware dialog, or null. */
    HardwareDialog hardwareDialog();

    void setHardwareDialog(HardwareDialog d);
}
