package org.parpe.gui.sweep;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.BooleanSupplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.ImageLoader;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Shell;
import org.parpe.gui.app.Gui;
import org.parpe.gui.automation.Screenshot;

/** What the sweep dialog's GUI tests share: the display, bounded waits, clicks and screenshots. */
final class Ui {
    static final long WAIT_MS = 60_000;

    private Ui() {
    }

    /** The display; fails with a hint when there is no X server. */
    static Display display() {
        return Gui.display();
    }

    /** Runs the event loop until {@code done} holds; fails after {@link #WAIT_MS}. */
    static void pump(BooleanSupplier done, String what) {
        Gui.pump(done, what, WAIT_MS);
    }

    /** What a text box or a spin box shows. */
    static String text(org.eclipse.swt.widgets.Control box) {
        return box instanceof org.eclipse.swt.widgets.Spinner s ? s.getText() : ((org.eclipse.swt.widgets.Text) box).getText();
    }

    /** Handles events for a moment, so that layouts and paints are done. */
    static void settle() {
        Gui.settle();
    }

    /** Presses {@code b} as a click would: its selection listeners run on the UI thread. */
    static void click(Button b) {
        assertTrue(b.isEnabled(), "the button '" + b.getText() + "' is disabled");
        b.notifyListeners(SWT.Selection, new Event());
    }

    /** Saves a screenshot of {@code shell} under the artefacts folder, checks it is not blank, returns its path. */
    static Path screenshot(Shell shell, String name) throws Exception {
        Path dir = Path.of(System.getProperty("parpe.artefacts", "target/gui-test-artefacts"));
        Files.createDirectories(dir);
        Path f = dir.resolve(name);
        Screenshot.save(shell, f);
        ImageData d = new ImageLoader().load(f.toString())[0];
        assertTrue(d.width > 600 && d.height > 400, "screenshot too small: " + d.width + "x" + d.height);
        assertTrue(Screenshot.distinctColours(d, 64) >= 64, "screenshot " + f + " looks blank");
        return f;
    }

    /** Ticks Vary for parameter {@code name} of {@code dialog}'s Sweep tab with its range and number of values. */
    static void vary(SweepDialog dialog, String name, String from, String to, int values) {
        SweepTab.Line l = dialog.sweepTab().line(name);
        org.junit.jupiter.api.Assertions.assertNotNull(l, "no line for parameter " + name);
        l.vary().setSelection(true);
        l.from().setText(from);
        l.to().setText(to);
        l.values().setText(Integer.toString(values));
    }

    /** Stops {@code dialog}'s runs, if any, and closes it. */
    static void close(SweepDialog dialog) {
        if (dialog != null && !dialog.shell().isDisposed()) {
            if (dialog.running()) {
                click(dialog.stopButton());
                pump(() -> !dialog.running(), "the sweep to stop");
            }
            dialog.shell().dispose();
        }
    }
}
