package org.parpe.gui.files;

import org.parpe.gui.text.UiMsg;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.model.Program;
import org.parpe.gui.panels.RobotChoice;
import org.parpe.sim.SimTarget;
import org.parpe.sim.bridge.Export;

/**
 * File → Export Robot…: the robot in MJCF, URDF or SDF, as {@code parpe export --target
 * mjcf|urdf|sdf --robot ROBOT --out DIR} writes it ({@link Export}, docs/bridges.md). A window
 * beside the IDE (not modal) with the format, the robot (starting on the open script's choice in
 * the 3D view's bar), the folder and Export; the export runs on a thread of its own, and what it
 * wrote or why it refused (located, also in Problems) shows in the window. Widgets on the UI thread only.
 */
public final class ExportRobotDialog {

    private final ExportWindow window;
    private final Combo target;
    private final RobotChoice robot;
    private final Supplier<Program> program;
    private final Consumer<List<Diagnostic>> problems;
    private volatile boolean busy;

    private ExportRobotDialog(Shell parent, Supplier<Program> program, String currentRobot, Consumer<List<Diagnostic>> problems) {
        this.program = program;
        this.problems = problems;
        window = new ExportWindow(parent, UiMsg.EXPORT_ROBOT_TITLE.text());
        target = window.combo(UiMsg.EXPORT_FORMAT.text(), new String[] {"MJCF (MuJoCo)", UiMsg.EXPORT_FORMAT_URDF.text(), "SDF (Gazebo)"});
        window.label(UiMsg.VIEW_ROBOT.text());
        robot = new RobotChoice(window.shell(), currentRobot);
        robot.control().setLayoutData(ExportWindow.span());
        window.finish("robot-export", UiMsg.EXPORT_ROBOT_FOLDER.text(), 90, this::export);
    }

    /**
     * Opens the window over {@code parent} for the open script {@code program} (gives null: none,
     * or one with errors) whose robot choice is {@code currentRobot}; located errors also go to {@code problems}.
     */
    public static ExportRobotDialog open(Shell parent, Supplier<Program> program, String currentRobot,
                                         Consumer<List<Diagnostic>> problems) {
        ExportRobotDialog d = new ExportRobotDialog(parent, program, currentRobot, problems);
        d.window.open(parent);
        return d;
    }

    public Shell shell() {
        return window.shell();
    }

    /** Chooses the format by its {@code --target} name: mjcf, urdf or sdf (tests, automation). */
    public void setTarget(String name) {
        target.select(Export.TARGETS.indexOf(name));
    }

    public void setFolder(Path dir) {
        window.setFolder(dir);
    }

    /** The robot choice (tests). */
    public RobotChoice robot() {
        return robot;
    }

    /** What the last export wrote or why it refused ("" before one). */
    public String message() {
        return window.message();
    }

    /** Answers this window's questions with {@code q} instead of dialogs (tests). */
    public void answerWith(FileActions.Questions q) {
        window.answerWith(q);
    }

    /** Whether an export is being written. */
    public boolean busy() {
        return busy;
    }

    /** Starts the export of the chosen robot into the chosen folder on a thread of its own. */
    public void export() {
        if (busy) {
            return;
        }
        String format = Export.TARGETS.get(Math.max(0, target.getSelectionIndex()));
        String spec = robot.robot();
        Program program = this.program.get();
        if (SimTarget.AUTO.equals(spec) && program == null) {
            window.say(UiMsg.AUTO_NEEDS_SCRIPT.text());
            return;
        }
        String chosen = SimTarget.AUTO.equals(spec) ? SimTarget.autoSpec(program) : spec;
        int[] ids = program == null ? new int[0] : program.moduleIds();
        Path dir = window.folder();
        busy = true;
        window.exporting(true);
        window.say(UiMsg.EXPORTING.text(chosen, format.toUpperCase(Locale.ROOT)));
        Display display = window.shell().getDisplay();
        background(() -> {
            DiagnosticList diags = new DiagnosticList();
            Export.Robot r = Export.robot(format, chosen, ids, diags);
            String refused = r == null ? null : Export.refusal(dir, r.files().keySet());
            if (r == null) {
                StringBuilder b = new StringBuilder(UiMsg.NOTHING_WRITTEN.text(UiMsg.ROBOT_CANNOT_BE_EXPORTED.text(chosen)) + "\n");
                diags.all().forEach(d -> b.append(d.format()).append('\n'));
                display.asyncExec(() -> done(b.toString().trim(), diags.all()));
            } else if (refused != null) {
                display.asyncExec(() -> done(UiMsg.NOTHING_WRITTEN.text(refused), List.of()));
            } else {
                List<Path> taken = ExportWindow.existing(dir, r.files().keySet());
                display.asyncExec(() -> replaceAndWrite(r, chosen, dir, taken));
            }
        });
    }

    /** UI thread: asks before replacing the user's files, then writes on a thread of its own. */
    private void replaceAndWrite(Export.Robot r, String spec, Path dir, List<Path> taken) {
        if (window.shell().isDisposed()) {
            busy = false;
            return;
        }
        if (!window.mayReplace(dir, taken, spec)) {
            busy = false;
            window.exporting(false);
            return;
        }
        Display display = window.shell().getDisplay();
        background(() -> {
            String text = write(r, spec, dir);
            display.asyncExec(() -> done(text, List.of()));
        });
    }

    private static void background(Runnable work) {
        Thread t = new Thread(work, "parpe-export-robot");
        t.setDaemon(true);
        t.start();
    }

    /** Writes the files of {@code r}, all or nothing; returns what to tell the user (off the UI thread). */
    private static String write(Export.Robot r, String spec, Path dir) {
        try {
            Export.write(dir, r.files());
        } catch (IOException e) {
            return UiMsg.NOTHING_WRITTEN.text(UiMsg.CANNOT_WRITE_INTO.text(dir, e.getMessage()));
        }
        return UiMsg.WROTE_ROBOT.text(String.join(", ", r.files().keySet()), dir, spec, r.summary());
    }

    private void done(String text, List<Diagnostic> diagnostics) {
        busy = false;
        if (window.shell().isDisposed()) {
            return;
        }
        window.exporting(false);
        window.say(text);
        if (!diagnostics.isEmpty()) {
            problems.accept(diagnostics);
        }
    }
}
