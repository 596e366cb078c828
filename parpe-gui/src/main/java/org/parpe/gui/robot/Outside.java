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
import org.parpe.gui.editor.Validator;
import org.parpe.gui.panels.FileDialogs;
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
                return FileDialogs.ask(shell, SWT.SAVE, "Make the robot editable: save it as", "*.xml",
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
        Path p = questions.open("Kit file");
        if (p == null) {
            return false;
        }
        DiagnosticList diags = new DiagnosticList();
        Kit k = Kit.read(p, diags);
        if (k == null) {
            say.accept(diags.all().isEmpty() ? "Cannot read the kit " + p : diags.all().get(0).format());
            return false;
        }
        kit = k;
        host.prefs().put(KIT, p.toAbsolutePath().toString());
        say.accept("Kit " + p.getFileName() + ": the builder keeps to it");
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
            say.accept("Cannot write " + target + ": " + e.getMessage());
            return Optional.empty();
        }
        host.chooseRobot(target.toString());
        say.accept("Wrote " + target.getFileName() + "; it is now the script's robot (Edit robot opens it)");
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
                say.accept("Try it needs the configuration saved");
                return Optional.empty();
            }
            robot = host.file().toAbsolutePath().toString();
            script = script != null ? script : lastScript();
        } else {
            robot = shown.kind() == Shown.Kind.FILE ? shown.config().toString() : shown.spec();
        }
        if (script == null || robot == null) {
            say.accept(robot == null ? "No robot to try" : "No script to try: open one, or pick one");
            return Optional.empty();
        }
        host.tryIt(script, robot);
        say.accept("Trying " + Path.of(script.file()).getFileName() + " on this robot");
        return Optional.of(script);
    }

    /** The script last loaded in the IDE, or the one the user picks; null when none loads. */
    private Program lastScript() {
        String last = host.prefs().get(LAST_SCRIPT, null);
        Path p = last != null && Files.isRegularFile(Path.of(last)) ? Path.of(last) : questions.open("Script to try");
        if (p == null) {
            return null;
        }
        try {
            LoadResult r = Validator.load(p, InputFiles.readText(p), Map.of());
            if (r.program() == null) {
                say.accept(r.diagnostics().isEmpty() ? "The script does not load" : r.diagnostics().get(0).format());
            }
            return r.program();
        } catch (IOException e) {
            say.accept("Cannot read " + p + ": " + e.getMessage());
            return null;
        }
    }
}
