package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;
import java.util.Locale;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.PlateSink;
import org.parpe.core.run.PlatesByHand;
import org.parpe.gui.run.RunController;

/**
 * Docking on hardware without latching plates (PARSL.md §14, docs/decisions.md): at every tick
 * with plate actions the run pauses before its next tick and the IDE asks the user to join or
 * part those plates by hand; <b>Continue</b> resumes the run, <b>Stop</b> ends it, closing the
 * question leaves the run paused (the toolbar's Run resumes it). The command line warns once per
 * plate instead ({@link PlatesByHand}), as a terminal cannot wait for hands.
 */
final class HandDocking implements PlateSink {
    /** The question's title (tests find its window by it). */
    static String title() {
        return UiMsg.HAND_TITLE.text();
    }

    private final IdeWindow ide;
    private final RunController controller;
    private final int[] ids;

    /** Asks in {@code ide} for the plates of the modules {@code ids} (ascending), pausing {@code controller}'s run. */
    HandDocking(IdeWindow ide, RunController controller, int[] ids) {
        this.ide = ide;
        this.controller = controller;
        this.ids = ids.clone();
    }

    /** On the engine thread: pauses the run and asks on the UI thread. */
    @Override
    public void plates(long tick, double time, byte[] actions, SourcePos[] where) {
        StringBuilder what = new StringBuilder(UiMsg.HAND_AT.text(String.format(Locale.ROOT, "%.3f", time)));
        for (int j = 0; j < actions.length; j++) {
            if (actions[j] != NONE) {
                what.append('\n').append((actions[j] == ARM ? UiMsg.HAND_ARMS : UiMsg.HAND_RELEASES).text(j & 1, ids[j >> 1],
                        PlatesByHand.task(actions[j])));
            }
        }
        what.append("\n\n").append(UiMsg.HAND_DO_IT.text());
        controller.setPaused(true);
        String text = what.toString();
        Shell shell = ide.shell;
        if (!shell.isDisposed()) {
            shell.getDisplay().asyncExec(() -> ask(text));
        }
    }

    private void ask(String text) {
        if (ide.shell.isDisposed() || !controller.running()) {
            return;
        }
        ide.status.setMessage(UiMsg.HAND_PAUSED.text());
        ide.runStateChanged();
        MessageDialog d = new MessageDialog(ide.shell, title(), null, text, MessageDialog.INFORMATION, 0,
                UiMsg.HAND_CONTINUE.text(), UiMsg.TOOL_STOP.text()) {
            @Override
            protected void buttonPressed(int button) {
                super.buttonPressed(button);
                if (button == 1) {
                    controller.stop();
                } else if (controller.running()) {
                    controller.setPaused(false);
                    ide.status.setMessage(UiMsg.RUN_RUNNING.text());
                }
                ide.runStateChanged();
            }
        };
        d.setBlockOnOpen(false);
        d.open();
    }
}
