package org.parpe.gui.app;

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
    static final String TITLE = "Join or part plates by hand";

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
        StringBuilder what = new StringBuilder(String.format(Locale.ROOT, "At t = %.3f s the script", time));
        for (int j = 0; j < actions.length; j++) {
            if (actions[j] != NONE) {
                what.append(String.format(Locale.ROOT, "%n\u2022 %s plate %d of module %d: %s", actions[j] == ARM
                        ? "arms" : "releases", j & 1, ids[j >> 1], PlatesByHand.task(actions[j])));
            }
        }
        what.append(String.format(Locale.ROOT, "%n%nThese modules have no latching plates. The run is paused: "
                + "do it by hand, then press Continue."));
        controller.setPaused(true);
        String text = what.toString();
        Shell shell = ide.shell();
        if (!shell.isDisposed()) {
            shell.getDisplay().asyncExec(() -> ask(text));
        }
    }

    private void ask(String text) {
        if (ide.shell().isDisposed() || !controller.running()) {
            return;
        }
        ide.status().setMessage("Paused: join or part plates by hand, then Continue");
        ide.runStateChanged();
        MessageDialog d = new MessageDialog(ide.shell(), TITLE, null, text, MessageDialog.INFORMATION, 0,
                "Continue", "Stop") {
            @Override
            protected void buttonPressed(int button) {
                super.buttonPressed(button);
                if (button == 1) {
                    controller.stop();
                } else if (controller.running()) {
                    controller.setPaused(false);
                    ide.status().setMessage("Running");
                }
                ide.runStateChanged();
            }
        };
        d.setBlockOnOpen(false);
        d.open();
    }
}
