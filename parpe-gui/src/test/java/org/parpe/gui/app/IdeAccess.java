package org.parpe.gui.app;

import java.nio.file.Path;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.model.Program;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.diagram.DiagramPane;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.files.Examples;
import org.parpe.gui.files.FileActions;
import org.parpe.gui.grid.GridPane;
import org.parpe.gui.hardware.HardwareDialog;
import org.parpe.gui.help.TutorialWindow;
import org.parpe.gui.panels.ProblemsView;
import org.parpe.gui.pose.PosePanel;
import org.parpe.gui.robot.RobotTab;
import org.parpe.gui.run.RunOn;
import org.parpe.gui.view3d.View3D;

/**
 * {@link Gui}'s helpers and the window's package-private parts, for GUI tests of other packages:
 * the one way they reach the window's parts (issue 32, item 2: the window has no public getter;
 * the main code of other packages reaches it through its host interfaces).
 */
public final class IdeAccess {
    private IdeAccess() {
    }

    /** A new automated IDE window with its settings in {@code home}, after its first validation. */
    public static IdeWindow openIde(Path home) {
        return Gui.openIde(home);
    }

    /**
     * Asks what closing the window asks, without closing it: {@code answer} gets each question of
     * the file's (title and message) and returns the button pressed; a message box of the Pose
     * panel's is recorded in {@code asked} as well and closed. True when the window would close.
     */
    public static boolean closeRequested(IdeWindow ide, java.util.List<String> asked, java.util.function.ToIntFunction<String> answer) {
        ide.files.answerWith((title, message, buttons) -> {
            asked.add(title + ": " + message);
            return answer.applyAsInt(message);
        });
        org.eclipse.swt.widgets.Display d = ide.shell.getDisplay();
        boolean[] done = new boolean[1];
        Runnable[] watch = new Runnable[1];
        watch[0] = () -> {
            for (Shell s : d.getShells()) {
                if (!s.isDisposed() && s != ide.shell && s.getText().startsWith("Unsaved")) {
                    asked.add(s.getText());
                    s.dispose();
                }
            }
            if (!done[0]) {
                d.timerExec(200, watch[0]);
            }
        };
        d.timerExec(200, watch[0]);
        try {
            return ide.closeRequested();
        } finally {
            done[0] = true;
        }
    }

    /** The chart of the Joint angles panel. */
    public static org.eclipse.swt.widgets.Control plotChart(IdeWindow ide) {
        return ide.plots.chart().control();
    }

    /** Ends any run and closes the window. */
    /** Help → Tutorial, docked beside the outline (as where the screen has no room for its own window); fails if it opened elsewhere. */
    public static void openTutorialDocked(IdeWindow ide) {
        ide.tutorialDock.open(dock -> TutorialWindow.docked(dock, Examples.tutorialFolder(), p -> { }, code -> { }));
        org.junit.jupiter.api.Assertions.assertNotNull(ide.tutorialDock.tutorial(), "the docked tutorial");
    }

    public static void closeIde(IdeWindow ide) {
        Gui.closeIde(ide);
    }

    /** Opens {@code file} as File > Open does and waits until it is in the editor. */
    public static void open(IdeWindow ide, Path file) {
        Gui.open(ide, file);
    }

    /** Answers "Don't Save" whenever the window asks about unsaved changes (File > New over an edited text). */
    public static void dontSave(IdeWindow ide) {
        ide.files.answerWith((title, message, buttons) -> 1);
    }

    /** Runs the event loop until {@code done} holds (bounded). */
    public static void pump(BooleanSupplier done, String what) {
        Gui.pump(done, what);
    }

    /** Lets layouts and paints finish. */
    public static void settle() {
        Gui.settle();
    }

    /** Saves a screenshot as evidence and checks it is not blank. */
    public static void screenshot(Shell shell, String name) throws Exception {
        Gui.screenshot(shell, name);
    }

    /** Whether a run is going on. */
    public static boolean running(IdeWindow ide) {
        return ide.runs.running();
    }

    /** Runs the editor's script on {@code target} for {@code seconds} of simulated time, as fast as possible. */
    public static void run(IdeWindow ide, RunOn target, double seconds, Consumer<RunOutcome> onEnd) {
        ide.toolbar.setTarget(target);
        ide.toolbar.setSpeed(org.parpe.gui.run.Speed.MAX);
        ide.runs.run(false, seconds, onEnd);
    }

    /** Stops the run, if any, and waits until its end has reached the window. */
    public static void endRun(IdeWindow ide) {
        Gui.endRun(ide);
    }

    /** The Run log's text. */
    public static String runLog(IdeWindow ide) {
        return ide.runLog().getText();
    }

    /** The status bar's message. */
    public static String status(IdeWindow ide) {
        return ide.status.message();
    }

    /**
     * Opens Run > Hardware…, connects to {@code port} with {@code protocol} at {@code baud} as a
     * user would, and waits until {@code servos} servos are listed.
     */
    public static void connectHardware(IdeWindow ide, String port, String protocol, int baud, int servos) {
        HardwareDialog d = HardwareDialog.open(ide.hardware);
        d.widgets().port().setText(port);
        d.widgets().protocol().select(d.widgets().protocol().indexOf(protocol));
        d.widgets().baud().setText(Integer.toString(baud));
        // A scan on a busy machine may miss replies (20 ms read timeout): try a few times, as a user would.
        for (int attempt = 0; attempt < 4 && d.servos().size() != servos; attempt++) {
            for (org.eclipse.swt.widgets.Control c : allChildren(d.shell())) {
                if (c instanceof org.eclipse.swt.widgets.Button b && b.getText().equals("Connect")) {
                    b.notifyListeners(org.eclipse.swt.SWT.Selection, new org.eclipse.swt.widgets.Event());
                }
            }
            long shortWait = System.currentTimeMillis() + 3000;
            Gui.pump(() -> d.widgets().message().getText().startsWith("Looking") || d.servos().size() == servos
                    || System.currentTimeMillis() > shortWait, "the dialog to start looking");
            Gui.pump(() -> !d.widgets().message().getText().startsWith("Looking"), "the dialog to finish looking");
            Gui.settle();
        }
        if (d.servos().size() != servos || d.widgets().table().getItemCount() != servos) {
            throw new org.opentest4j.AssertionFailedError("expected " + servos + " servos in the Hardware dialog; it says: "
                    + d.widgets().message().getText());
        }
    }

    /** Closes the Hardware dialog (and its bus) and waits until the bus is closed. */
    public static void closeHardware(IdeWindow ide) throws InterruptedException {
        HardwareDialog d = ide.hardware.hardwareDialog();
        if (d != null && !d.shell().isDisposed()) {
            d.shell().close();
            Gui.pump(() -> d.shell().isDisposed(), "the Hardware dialog to close");
            d.session().awaitClosed(5000);
        }
    }

    /** Every control under {@code parent}, depth first. */
    public static java.util.List<org.eclipse.swt.widgets.Control> allChildren(org.eclipse.swt.widgets.Composite parent) {
        java.util.List<org.eclipse.swt.widgets.Control> out = new java.util.ArrayList<>();
        for (org.eclipse.swt.widgets.Control c : parent.getChildren()) {
            out.add(c);
            if (c instanceof org.eclipse.swt.widgets.Composite k) {
                out.addAll(allChildren(k));
            }
        }
        return out;
    }

    /** Selects the simulated robot (a generator name) as the 3D view's picker does. */
    public static void robot(IdeWindow ide, String name) {
        ide.viewBar.select(name);
    }

    /** Chooses the world file {@code file} in the 3D view's World picker, as the window's runs then use it. */
    public static void world(IdeWindow ide, Path file) {
        ide.viewBar.world().choose(file.toAbsolutePath().normalize());
    }

    /** The IDE's run controller (its breakpoints, its pause, the engine of the run). */
    public static org.parpe.gui.run.RunController controller(IdeWindow ide) {
        return ide.runs.controller();
    }

    // The window's parts (IdeWindow's package-private getters).

    public static Shell shell(IdeWindow ide) {
        return ide.shell;
    }

    public static ParslEditor editor(IdeWindow ide) {
        return ide.editor;
    }

    /** The Diagram pane beside the 3D view. */
    public static DiagramPane diagram(IdeWindow ide) {
        return ide.diagram;
    }

    /** The gait-table grid beside the editor. */
    public static GridPane grid(IdeWindow ide) {
        return ide.grid;
    }

    public static FileActions files(IdeWindow ide) {
        return ide.files;
    }

    public static RunActions runs(IdeWindow ide) {
        return ide.runs;
    }

    /** The status bar ({@link #status} is its message). */
    public static StatusBar statusBar(IdeWindow ide) {
        return ide.status;
    }

    public static RunToolBar toolbar(IdeWindow ide) {
        return ide.toolbar;
    }

    public static ProblemsView problems(IdeWindow ide) {
        return ide.problems();
    }

    public static View3D view(IdeWindow ide) {
        return ide.view;
    }

    public static ViewBar viewBar(IdeWindow ide) {
        return ide.viewBar;
    }

    /** The Pose panel. */
    public static PosePanel pose(IdeWindow ide) {
        return ide.pose;
    }

    /** Brings the Pose panel to the front. */
    public static void showPosePanel(IdeWindow ide) {
        ide.bottom.showPose();
    }

    /** The Robot tab beside the 3D view. */
    public static RobotTab robotTab(IdeWindow ide) {
        return ide.robotTab;
    }

    /** The last program that loaded, or null. */
    public static Program program(IdeWindow ide) {
        return ide.program();
    }

    /** How many validation results have been shown. */
    public static int validations(IdeWindow ide) {
        return ide.validations();
    }
}
