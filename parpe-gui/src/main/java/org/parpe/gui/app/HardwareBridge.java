package org.parpe.gui.app;

import org.eclipse.swt.widgets.Control;
import org.parpe.gui.hardware.HardwareDialog;
import org.parpe.gui.hardware.HardwareHost;
import org.parpe.gui.hardware.PortChoice;

/**
 * The IDE window as the Hardware dialog sees it, and the window's one dialog and the bus it
 * holds. UI thread only, except {@link #held}.
 */
final class HardwareBridge extends WindowBridge implements HardwareHost {
    private HardwareDialog dialog;
    private volatile String held;

    HardwareBridge(IdeWindow ide) {
        super(ide);
    }

    @Override
    public PortChoice portChoice() {
        return ide.toolbar;
    }

    @Override
    public void hardwareGone() {
        ide.pose.hardwareGone();
    }

    @Override
    public Control posePanel() {
        return ide.pose.control();
    }

    @Override
    public HardwareDialog hardwareDialog() {
        return dialog;
    }

    @Override
    public void setHardwareDialog(HardwareDialog d) {
        dialog = d;
    }

    @Override
    public void setHardwareHeld(String state) {
        held = state;
    }

    /** What the status bar says while the Hardware dialog holds a bus, or null (any thread). */
    String held() {
        return held;
    }
}
