package org.parpe.gui.files;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.DirectoryDialog;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.model.Program;
import org.parpe.gui.panels.FileDialogs;
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
    private static final String[] LABELS = {"MJCF (MuJoCo)", "URDF (ROS tools)", "SDF (Gazebo)"};

    private final Shell shell;
    private final Display display;
    private final Combo target;
    private final RobotChoice robot;
    private final Text folder;
    private final Button export;
    private final Text message;
    private final Supplier<Program> program;
    private final Consumer<List<Diagnostic>> problems;
    private volatile boolean busy;
    private FileActions.Questions questions;

    private ExportRobotDialog(Shell parent, Supplier<Program> program, String currentRobot, Consumer<List<Diagnostic>> problems) {
        this.program = program;
        this.problems = problems;
        shell = new Shell(parent, SWT.DIALOG_TRIM | SWT.RESIZE | SWT.MODELESS);
        display = shell.getDisplay();
        shell.setText("Export Robot");
        shell.setLayout(new GridLayout(3, false));
        new Label(shell, SWT.NONE).setText("Format:");
        target = new Combo(shell, SWT.READ_ONLY);
        for (String l : LABELS) {
            target.add(l);
        }
        target.select(0);
        target.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        new Label(shell, SWT.NONE).setText("Robot:");
        robot = new RobotChoice(shell, currentRobot);
        robot.control().setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        new Label(shell, SWT.NONE).setText("Folder:");
        folder = new Text(shell, SWT.BORDER);
        folder.setText(FileDialogs.start().resolve("robot-export").toString());
        GridData fd = new GridData(SWT.FILL, SWT.CENTER, true, false);
        fd.widthHint = 420;
        folder.setLayoutData(fd);
        button("Browse\u2026", this::askFolder);
        message = new Text(shell, SWT.MULTI | SWT.READ_ONLY | SWT.WRAP | SWT.V_SCROLL | SWT.BORDER);
        GridData md = new GridData(SWT.FILL, SWT.FILL, true, true, 3, 1);
        md.heightHint = 90;
        message.setLayoutData(md);
        new Label(shell, SWT.NONE).setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        export = button("Export", this::export);
        shell.setDefaultButton(export);
        questions = (title, text, buttons) -> new org.eclipse.jface.dialogs.MessageDialog(shell, title, null, text,
                org.eclipse.jface.dialogs.MessageDialog.QUESTION, buttons, 1).open();
    }

    /**
     * Opens the window over {@code parent} for the open script {@code program} (gives null: none,
     * or one with errors) whose robot choice is {@code currentRobot}; located errors also go to {@code problems}.
     */
    public static ExportRobotDialog open(Shell parent, Supplier<Program> program, String currentRobot,
                                         Consumer<List<Diagnostic>> problems) {
        ExportRobotDialog d = new ExportRobotDialog(parent, program, currentRobot, problems);
        d.shell.pack();
        org.eclipse.swt.graphics.Rectangle over = parent.getBounds();
        org.eclipse.swt.graphics.Point size = d.shell.getSize();
        d.shell.setLocation(over.x + Math.max(0, (over.width - size.x) / 2), over.y + Math.max(0, (over.height - size.y) / 3));
        d.shell.open();
        return d;
    }

    public Shell shell() {
        return shell;
    }

    /** Chooses the format by its {@code --target} name: mjcf, urdf or sdf (tests, automation). */
    public void setTarget(String name) {
        target.select(Export.TARGETS.indexOf(name));
    }

    public void setFolder(Path dir) {
        folder.setText(dir.toString());
    }

    /** The robot choice (tests). */
    public RobotChoice robot() {
        return robot;
    }

    /** What the last export wrote or why it refused ("" before one). */
    public String message() {
        return message.getText();
    }

    /** Answers this window's questions with {@code q} instead of dialogs (tests). */
    public void answerWith(FileActions.Questions q) {
        questions = q;
    }

    /** Whether an export is being written. */
    public boolean busy() {
        return busy;
    }

    private Button button(String text, Runnable action) {
        Button b = new Button(shell, SWT.PUSH);
        b.setText(text);
        b.addListener(SWT.Selection, e -> action.run());
        return b;
    }

    private void askFolder() {
        DirectoryDialog d = new DirectoryDialog(shell);
        d.setText("Export Into");
        d.setMessage("The folder the robot's file is written into");
        d.setFilterPath(FileDialogs.start().toString());
        String chosen = d.open();
        if (chosen != null) {
            folder.setText(chosen);
        }
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
            message.setText("'auto' picks the robot from the script, and there is no script without errors open:"
                    + " choose a robot (a generator or a configuration file)");
            return;
        }
        String chosen = SimTarget.AUTO.equals(spec) ? SimTarget.autoSpec(program) : spec;
        int[] ids = program == null ? new int[0] : program.moduleIds();
        Path dir = Path.of(folder.getText().trim()).toAbsolutePath();
        busy = true;
        export.setEnabled(false);
        message.setText("Exporting " + chosen + " as " + format.toUpperCase(Locale.ROOT) + "\u2026");
        background(() -> {
            DiagnosticList diags = new DiagnosticList();
            Export.Robot r = Export.robot(format, chosen, ids, diags);
            String refused = r == null ? null : Export.refusal(dir, r.files().keySet());
            List<Path> taken = r == null || refused != null ? List.of() : taken(dir, r);
            if (r == null) {
                StringBuilder b = new StringBuilder("Nothing written: the robot '" + chosen + "' cannot be exported\n");
                diags.all().forEach(d -> b.append(d.format()).append('\n'));
                finish(b.toString().trim(), diags.all());
            } else if (refused != null) {
                finish("Nothing written: " + refused, List.of());
            } else if (taken.isEmpty()) {
                finish(write(r, chosen, dir), List.of());
            } else {
                display.asyncExec(() -> askToReplace(r, chosen, dir, taken));
            }
        });
    }

    /** The files of {@code r} that are in {@code dir} already (regular files: {@link Export#refusal} refused others). */
    private static List<Path> taken(Path dir, Export.Robot r) {
        return r.files().keySet().stream().map(dir::resolve).filter(Files::exists).toList();
    }

    /**
     * The folder has files of the export's names: they are the user's (an earlier export, perhaps
     * edited since), so they are replaced only when the user says so; the CLI's {@code --out}
     * names the folder on purpose and replaces them (docs/cli.md, output rules).
     */
    private void askToReplace(Export.Robot r, String spec, Path dir, List<Path> taken) {
        if (shell.isDisposed()) {
            busy = false;
            return;
        }
        String names = taken.stream().map(Path::toString).collect(java.util.stream.Collectors.joining(", "));
        String files = taken.stream().map(p -> p.getFileName().toString()).collect(java.util.stream.Collectors.joining(", "));
        int answer = questions.ask("Replace " + (taken.size() == 1 ? "file" : "files"), "The folder " + dir + " already has "
                + files + ". Replace " + (taken.size() == 1 ? "it" : "them") + " with the export of " + spec + "?",
                "Replace", "Cancel");
        if (answer == 0) {
            background(() -> finish(write(r, spec, dir), List.of()));
        } else {
            done("Nothing written: " + names + (taken.size() == 1 ? " is" : " are") + " kept", List.of());
        }
    }

    /** Runs {@code work} on a thread of its own (an export reads configurations and writes files). */
    private static void background(Runnable work) {
        Thread t = new Thread(work, "parpe-export-robot");
        t.setDaemon(true);
        t.start();
    }

    /** Shows the outcome of an export, from any thread. */
    private void finish(String text, List<Diagnostic> diagnostics) {
        display.asyncExec(() -> done(text, diagnostics));
    }

    /** Writes the files of {@code r}, all or nothing; returns what to tell the user (off the UI thread). */
    private static String write(Export.Robot r, String spec, Path dir) {
        try {
            Export.write(dir, r.files());
        } catch (IOException e) {
            return "Nothing written: cannot write into '" + dir + "': " + e.getMessage();
        }
        return "Wrote " + String.join(", ", r.files().keySet()) + " to " + dir + " (" + spec + ": " + r.summary() + ")";
    }

    private void done(String text, List<Diagnostic> diagnostics) {
        busy = false;
        if (shell.isDisposed()) {
            return;
        }
        export.setEnabled(true);
        message.setText(text);
        if (!diagnostics.isEmpty()) {
            problems.accept(diagnostics);
        }
    }
}
