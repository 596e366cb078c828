package org.parpe.gui.view3d;


import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Spinner;
import org.parpe.gui.text.PanelMsg;

/**
 * A small window beside the IDE with the camera of a chosen module (the paper's snake carried a
 * CCD camera for teleoperation through the rubble): the module ID to look from, and the view,
 * redrawn from the IDE's snapshots about 20 times a second while the window is open.
 */
public final class ModuleCameraWindow {
    private static final int FRAME_MS = 50;

    private final Shell shell;
    private final Spinner id;
    private final ModuleCameraView view;

    private ModuleCameraWindow(Shell parent, java.util.function.Supplier<org.parpe.sim.snapshot.SimSnapshot> source, int[] ids) {
        shell = new Shell(parent, SWT.SHELL_TRIM | SWT.TOOL);
        shell.setText(PanelMsg.CAMERA_TITLE.text());
        shell.setLayout(new GridLayout(1, false));
        Composite row = new Composite(shell, SWT.NONE);
        row.setLayout(new GridLayout(2, false));
        new Label(row, SWT.NONE).setText(PanelMsg.CAMERA_MODULE.text());
        id = new Spinner(row, SWT.BORDER);
        id.setValues(0, 0, 999, 0, 1, 10);
        id.setToolTipText(PanelMsg.CAMERA_MODULE_TIP.text());
        view = new ModuleCameraView(shell);
        view.control().setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        view.setSource(source);
        id.addListener(SWT.Selection, e -> view.setModule(id.getSelection()));
        if (ids.length > 0) {
            id.setSelection(ids[ids.length - 1]);
        }
        view.setModule(id.getSelection());
        shell.setSize(480, 400);
    }

    /** The camera's view (tests). */
    public ModuleCameraView view() {
        return view;
    }

    /**
     * Opens the window over {@code parent}, showing what {@code source} gives at each frame, looking from
     * the last of the script's modules {@code ids} (module 0 when there are none).
     */
    public static ModuleCameraWindow open(Shell parent, java.util.function.Supplier<org.parpe.sim.snapshot.SimSnapshot> source, int[] ids) {
        ModuleCameraWindow w = new ModuleCameraWindow(parent, source, ids);
        w.shell.open();
        w.tick();
        return w;
    }

    private void tick() {
        if (shell.isDisposed()) {
            return;
        }
        view.control().redraw();
        shell.getDisplay().timerExec(FRAME_MS, this::tick);
    }

    /** The window. */
    public Shell shell() {
        return shell;
    }

    /** Looks from module {@code module}. */
    public void setModule(int module) {
        id.setSelection(module);
        view.setModule(module);
    }
}
