package org.parpe.gui.files;

import org.parpe.gui.text.UiMsg;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.export.Board;
import org.parpe.core.model.Program;
import org.parpe.serial.export.ProgramExport;
import org.parpe.serial.export.SketchOptions;
import org.parpe.sim.bridge.Export;

/**
 * File → Export Program as C/Arduino…: the open script as C or as an Arduino sketch folder, as
 * {@code parpe export --target c|arduino} writes it ({@link ProgramExport}, docs/embedded.md). A
 * window beside the IDE (not modal) with the target, the board, the sketch's servos, the tick and
 * the folder; the export runs on a thread of its own, asks before it replaces files already in the
 * folder, writes every file in full before any replaces its old version ({@link Export#write}),
 * and shows what it wrote or why it refused (located errors also in Problems). Widgets on the UI thread only.
 */
public final class ExportProgramDialog {
    private static final String[] SERVOS = {"pwm", "dxl", "sts"};

    private final ExportWindow window;
    private final Combo target;
    private final Combo board;
    private final Combo servo;
    private final Button consoleSensors;
    private final Text tick;
    private final Supplier<Program> program;
    private final Consumer<List<Diagnostic>> problems;
    private volatile boolean busy;

    private ExportProgramDialog(Shell parent, Supplier<Program> program, Consumer<List<Diagnostic>> problems) {
        this.program = program;
        this.problems = problems;
        window = new ExportWindow(parent, UiMsg.EXPORT_PROGRAM_TITLE.text());
        Shell shell = window.shell();
        target = window.combo(UiMsg.EXPORT_TARGET.text(), new String[] {UiMsg.EXPORT_TARGET_C.text(), UiMsg.EXPORT_TARGET_ARDUINO.text()});
        board = window.combo(UiMsg.EXPORT_BOARD.text(), new String[0]);
        servo = window.combo(UiMsg.EXPORT_SERVOS.text(), new String[] {UiMsg.EXPORT_SERVO_PWM.text(), UiMsg.EXPORT_SERVO_DXL.text(),
                UiMsg.EXPORT_SERVO_STS.text()});
        window.label("");
        consoleSensors = new Button(shell, SWT.CHECK);
        consoleSensors.setText(UiMsg.EXPORT_CONSOLE_SENSORS.text());
        consoleSensors.setLayoutData(ExportWindow.span());
        window.label(UiMsg.EXPORT_TICK.text());
        tick = new Text(shell, SWT.BORDER);
        tick.setText("0.01");
        tick.setLayoutData(ExportWindow.span());
        window.finish("program-export", UiMsg.EXPORT_PROGRAM_FOLDER.text(), 110, this::export);
        target.addListener(SWT.Selection, e -> targetChanged());
        targetChanged();
    }

    /**
     * Opens the window over {@code parent} for the open script {@code program} (gives null: none,
     * or one with errors); located errors also go to {@code problems}.
     */
    public static ExportProgramDialog open(Shell parent, Supplier<Program> program, Consumer<List<Diagnostic>> problems) {
        ExportProgramDialog d = new ExportProgramDialog(parent, program, problems);
        d.window.open(parent);
        return d;
    }

    public Shell shell() {
        return window.shell();
    }

    /** Chooses the target by its {@code --target} name, c or arduino (tests, automation). */
    public void setTarget(String word) {
        target.select(ProgramExport.Target.valueOf(word.toUpperCase(java.util.Locale.ROOT)).ordinal());
        targetChanged();
    }

    /** Chooses the sketch's servos by their {@code --servo} name: pwm, dxl or sts. */
    public void setServo(String word) {
        servo.select(List.of(SERVOS).indexOf(word));
    }

    public void setFolder(Path dir) {
        window.setFolder(dir);
    }

    /** Answers the replace question with {@code q} instead of a dialog (tests). */
    public void answerWith(FileActions.Questions q) {
        window.answerWith(q);
    }

    /** What the last export wrote or why it refused ("" before one). */
    public String message() {
        return window.message();
    }

    /** Whether an export is being prepared or written. */
    public boolean busy() {
        return busy;
    }

    private ProgramExport.Target chosenTarget() {
        return ProgramExport.Target.values()[Math.max(0, target.getSelectionIndex())];
    }

    /** The boards and the sketch's options follow the target; the board starts on the target's default. */
    private void targetChanged() {
        ProgramExport.Target t = chosenTarget();
        board.removeAll();
        for (Board b : t.boards()) {
            board.add(b.word());
        }
        board.select(t.boards().indexOf(t.defaultBoard()));
        boolean sketch = t == ProgramExport.Target.ARDUINO;
        servo.setEnabled(sketch);
        consoleSensors.setEnabled(sketch);
    }

    /** The choices of the window as an export request, or null after saying what is wrong. */
    private ProgramExport.Request request() {
        ProgramExport.Target t = chosenTarget();
        try {
            double dt = Double.parseDouble(tick.getText().trim());
            SketchOptions sketch = t == ProgramExport.Target.ARDUINO ? SketchOptions.of(
                    SERVOS[Math.max(0, servo.getSelectionIndex())], List.of(), 1_000_000, null,
                    consoleSensors.getSelection()) : null;
            return new ProgramExport.Request(t, t.boards().get(Math.max(0, board.getSelectionIndex())), dt, sketch);
        } catch (NumberFormatException e) {
            window.say(UiMsg.NOTHING_WRITTEN.text(UiMsg.TICK_NOT_A_NUMBER.text(tick.getText().trim())));
        } catch (IllegalArgumentException e) {
            window.say(UiMsg.NOTHING_WRITTEN.text(e.getMessage()));
        }
        return null;
    }

    /** Starts the export of the open script into the chosen folder on a thread of its own. */
    public void export() {
        if (busy) {
            return;
        }
        Program p = program.get();
        if (p == null) {
            window.say(UiMsg.NOTHING_WRITTEN.text(UiMsg.NO_SCRIPT_WITHOUT_ERRORS.text()));
            return;
        }
        ProgramExport.Request q = request();
        if (q == null) {
            return;
        }
        Path out = window.folder();
        busy = true;
        window.exporting(true);
        window.say(UiMsg.EXPORTING.text(Path.of(p.file()).getFileName(), q.target().word()));
        Display display = window.shell().getDisplay();
        background(() -> {
            DiagnosticList diags = new DiagnosticList();
            ProgramExport.Result r = ProgramExport.export(p, q, diags);
            String refused = r == null ? UiMsg.PROGRAM_CANNOT_BE_EXPORTED.text(lines(diags.all())) : refusal(r, out);
            List<Path> existing = r == null ? List.of() : ExportWindow.existing(r.dir(out), r.files().keySet());
            display.asyncExec(() -> prepared(r, out, refused, existing, diags.all()));
        });
    }

    /** Off the UI thread: why the files cannot go into their folder, or null. */
    private static String refusal(ProgramExport.Result r, Path out) {
        Path dir = r.dir(out);
        String refused = Export.refusal(dir, r.files().keySet());
        try {
            return refused != null ? refused : ProgramExport.editedSketch(dir, r.files().keySet());
        } catch (IOException e) {
            return UiMsg.CANNOT_READ_FOLDER.text(dir, e.getMessage());
        }
    }

    /** On the UI thread: asks before replacing files, then writes on a thread of its own. */
    private void prepared(ProgramExport.Result r, Path out, String refused, List<Path> existing, List<Diagnostic> found) {
        if (window.shell().isDisposed()) {
            busy = false;
            return;
        }
        if (!found.isEmpty()) {
            problems.accept(found);
        }
        if (refused != null) {
            done(UiMsg.NOTHING_WRITTEN.text(refused));
            return;
        }
        Path dir = r.dir(out);
        if (!window.mayReplace(dir, existing, UiMsg.THE_PROGRAM.text())) {
            busy = false;
            window.exporting(false);
            return;
        }
        Display display = window.shell().getDisplay();
        background(() -> {
            String text;
            try {
                Export.write(dir, r.files());
                text = UiMsg.WROTE_FILES.text(r.files().size(), dir, r.memory().format());
            } catch (IOException e) {
                text = UiMsg.NOTHING_WRITTEN.text(UiMsg.CANNOT_WRITE_INTO.text(dir, e.getMessage()));
            }
            String said = text;
            display.asyncExec(() -> done(said));
        });
    }

    private static void background(Runnable work) {
        Thread t = new Thread(work, "parpe-export-program");
        t.setDaemon(true);
        t.start();
    }

    private static String lines(List<Diagnostic> ds) {
        return String.join("\n", ds.stream().map(Diagnostic::format).toList());
    }

    private void done(String text) {
        busy = false;
        if (window.shell().isDisposed()) {
            return;
        }
        window.exporting(false);
        window.say(text);
    }
}
