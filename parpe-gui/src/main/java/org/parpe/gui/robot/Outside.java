package org.parpe.gui.robot;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.io.AtomicFiles;
import org.parpe.core.load.LoadResult;
import org.parpe.core.model.Program;
import org.parpe.core.xml.InputFiles;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.gui.panels.FileDialogs;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.config.Kit;

/**
 * What the Robot tab does with files: "Make editable" (a generator written to a file beside the
 * script, never over another without asking, then the script's robot), the kit file, and "Try
 * it" (the script last open run on the robot; the configuration saved first).
 */
public final class Outside {
    private static final String KIT = "robot.kit";
    private static final String LAST_SCRIPT = "robot.lastScript";

    /** The questions the tab asks (file dialogs; tests answer them). */
    public interface Questions {
        /** The file to write the robot to ({@code proposed} beside the script); null: cancelled. Asks before replacing a file. */
        Path saveRobotAs(Path proposed);

        /** A file to open, titled {@code title} ("Kit file", "Script to try"); null: cancelled. */
        Path open(String title);
    }

    private final RobotHost host;
    private final Consumer<String> say;
    private Questions questions;
    private Kit kit;

    Outside(RobotHost host, Shell shell, Consumer<String> say) {
        this.host = host;
        this.say = say;
        questions = new Questions() {
            @Override
            public Path saveRobotAs(Path proposed) {
                return FileDialogs.ask(shell, SWT.SAVE, ToolMsg.ROBOT_SAVE_AS.text(), "*.xml",
                        proposed.getFileName().toString(), proposed.getParent());
            }

            @Override
            public Path open(String title) {
                return FileDialogs.ask(shell, SWT.OPEN, title, "*.xml", null, null);
            }
        };
        String k = host.prefs().get(KIT, null);
        if (k != null && Files.isRegularFile(Path.of(k))) {
            kit = Kit.read(Path.of(k), new DiagnosticList());
        }
    }

    void answerWith(Questions q) {
        questions = q;
    }

    /** The kit chosen (null: none, no limit). */
    Kit kit() {
        return kit;
    }

    /** A script loaded from {@code file}: "Try it" on a configuration runs it. */
    void scriptLoaded(Path file) {
        host.prefs().put(LAST_SCRIPT, file.toAbsolutePath().toString());
    }

    /** Asks for a kit file and reads it; true when the kit changed. */
    boolean chooseKit() {
        Path p = questions.open(ToolMsg.ROBOT_KIT_FILE.text());
        if (p == null) {
            return false;
        }
        DiagnosticList diags = new DiagnosticList();
        Kit k = Kit.read(p, diags);
        if (k == null) {
            say.accept(diags.all().isEmpty() ? ToolMsg.ROBOT_CANNOT_READ_KIT.text(p) : diags.all().get(0).format());
            return false;
        }
        kit = k;
        host.prefs().put(KIT, p.toAbsolutePath().toString());
        say.accept(ToolMsg.ROBOT_KIT_CHOSEN.text(p.getFileName()));
        return true;
    }

    /** Writes the generator shown to a file the user confirms and makes it the script's robot; what to show then. */
    Optional<Shown> makeEditable(Shown shown) {
        if (shown.kind() != Shown.Kind.GENERATOR) {
            return Optional.empty();
        }
        Path target = questions.saveRobotAs(Shown.besideScript(host.file()));
        if (target == null) {
            return Optional.empty();
        }
        target = target.toAbsolutePath().normalize();
        try {
            AtomicFiles.write(target, shown.draft().text()); // the robot shown: the generator sized for the script
        } catch (IOException | RuntimeException e) {
            say.accept(ToolMsg.ROBOT_CANNOT_WRITE.text(target, e.getMessage()));
            return Optional.empty();
        }
        host.chooseRobot(target.toString());
        say.accept(ToolMsg.ROBOT_WROTE.text(target.getFileName()));
        return Optional.of(Shown.ofFile(target));
    }

    /**
     * "Try it": runs the script on the robot shown. For a configuration in the editor, it is saved
     * first and the script is the last one loaded (else the one the user picks); returns the
     * script run, empty when nothing runs.
     */
    Optional<Program> tryIt(Shown shown, Program script) {
        String robot;
        if (shown.editable()) {
            if (!host.save()) {
                say.accept(ToolMsg.ROBOT_TRY_NEEDS_SAVED.text());
                return Optional.empty();
            }
            robot = host.file().toAbsolutePath().toString();
            script = script != null ? script : lastScript();
        } else {
            robot = shown.kind() == Shown.Kind.FILE ? shown.config().toString() : shown.spec();
        }
        if (script == null || robot == null) {
            say.accept(robot == null ? ToolMsg.ROBOT_NO_ROBOT_TO_TRY.text() : ToolMsg.ROBOT_NO_SCRIPT_TO_TRY.text());
            return Optional.empty();
        }
        host.tryIt(script, robot);
        say.accept(ToolMsg.ROBOT_TRYING.text(Path.of(script.file()).getFileName()));
        return Optional.of(script);
    }

    /** The script last loaded in the IDE, or the one the user picks; null when none loads. */
    private Program lastScript() {
        String last = host.prefs().get(LAST_SCRIPT, null);
        Path p = last != null && Files.isRegularFile(Path.of(last)) ? Path.of(last) : questions.open(ToolMsg.ROBOT_SCRIPT_TO_TRY.text());
        if (p == null) {
            return null;
        }
        try {
            LoadResult r = ScriptDocument.load(p, InputFiles.readText(p), Map.of());
            if (r.program() == null) {
                say.accept(r.diagnostics().isEmpty() ? ToolMsg.ROBOT_SCRIPT_DOES_NOT_LOAD.text() : r.diagnostics().get(0).format());
            }
            return r.program();
        } catch (IOException e) {
            say.accept(ToolMsg.ROBOT_CANNOT_READ.text(p, e.getMessage()));
            return null;
        }
    }
}
