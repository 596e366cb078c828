package org.parpe.gui.app;

import java.nio.file.Path;
import java.util.List;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Shell;
import org.parpe.gui.hardware.HardwareDialog;
import org.parpe.gui.hardware.HardwareHost;

/**
 * The IDE window as the Hardware dialog sees it, and the window's one dialog and the bus it
 * holds. UI thread only, except {@link #held}.
 */
final class HardwareBridge implements HardwareHost {
    private final IdeWindow ide;
    private HardwareDialog dialog;
    private volatile String held;

    HardwareBridge(IdeWindow ide) {
        this.ide = ide;
    }

    @Override
    public Shell shell() {
        return ide.shell();
    }

    @Override
    public String port() {
        return ide.toolbar().port();
    }

    @Override
    public void setPort(String port) {
        ide.toolbar().setPort(port);
    }

    @Override
    public String hardwareProfile() {
        return ide.toolbar().hardwareProfile();
    }

    @Override
    public void setHardwareProfile(String file) {
        ide.toolbar().setHardwareProfile(file);
    }

    @Override
    public void hardwareGone() {
        ide.pose().hardwareGone();
    }

    @Override
    public Control posePanel() {
        return ide.pose().control();
    }

    @Override
    public List<Path> openFiles() {
        return ide.files().openFiles();
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
