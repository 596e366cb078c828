package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.Speed;
import org.parpe.gui.run.RunOn;

/**
 * The IDE assembles runs as the command line does: what goes wrong while preparing or during a
 * run reaches the Problems view as located diagnostics (never "internal error"), and run-time
 * problems stay there when the text is validated again. Real widgets under Xvfb, bounded waits.
 */
class RunProblemsGuiTest {
    private static IdeWindow ide;
    private static Path dir;

    @BeforeAll
    static void openWindow() throws Exception {
        dir = Files.createTempDirectory("parpe-run-problems");
        ide = Gui.openIde(dir.resolve("home"));
    }

    @AfterAll
    static void closeWindow() {
        Gui.closeIde(ide);
    }

    @AfterEach
    void backToTheSimulator() {
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.viewBar.select("auto (from the script)");
    }

    /** Opens {@code text} as a file and waits for it to validate without errors. */
    private static Path open(String name, String text) throws Exception {
        Path f = dir.resolve(name);
        Files.writeString(f, text);
        int before = ide.validations();
        Gui.open(ide, f);
        Gui.pump(() -> ide.validations() > before && ide.program() != null
                && ide.program().file().endsWith(name), name + " to load");
        assertEquals(0, ide.problems().errorCount(), "script has errors: " + ide.problems().shown());
        return f;
    }

    private static RunOutcome runToEnd(double seconds) {
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        ide.toolbar.setSpeed(Speed.MAX);
        ide.runs.run(false, seconds, outcome::set);
        Gui.pump(() -> outcome.get() != null, "the run to end");
        // Problems reported from the engine thread arrive through asyncExec: let them in.
        Gui.settle();
        return outcome.get();
    }

    private static List<Diagnostic> shown(Severity s) {
        return ide.problems().shown().stream().filter(d -> d.severity() == s).toList();
    }

    private static String snake(String angle) {
        return "<program>\n<robot><structure><body elements=\"0..3\"/></structure></robot>\n"
                + "<main><b/></main>\n<behaviors><b><w group=\"body\"/></b></behaviors>\n"
                + "<automata><w states=\"s, t\"/></automata>\n"
                + "<states>\n<s angles=\"" + angle + "\"/>\n<t angles=\"0\"/></states>\n</program>\n";
    }

    @Test
    void hardwareWithoutAPortIsAProblemToFixNotAnInternalError() throws Exception {
        open("hw.xml", snake("20"));
        ide.toolbar.setTarget(RunOn.HARDWARE);
        ide.toolbar.setPort("");
        RunOutcome o = runToEnd(1);
        assertEquals(RunOutcome.Status.ERROR, o.status());
        assertFalse(o.message().contains("internal error"), o.message());
        List<Diagnostic> errors = shown(Severity.ERROR);
        assertTrue(errors.stream().anyMatch(d -> d.message().startsWith("no serial port chosen")), errors.toString());
    }

    @Test
    void aParslScriptChosenAsTheRobotIsALocatedProblem() throws Exception {
        Path script = open("robot-mixup.xml", snake("20"));
        ide.viewBar.useFile(script.toString());
        RunOutcome o = runToEnd(1);
        assertEquals(RunOutcome.Status.ERROR, o.status());
        assertFalse(o.message().contains("internal error"), o.message());
        List<Diagnostic> errors = shown(Severity.ERROR);
        assertTrue(errors.stream().anyMatch(d -> d.pos().file().equals(script.toString()) && d.pos().line() == 1
                && d.message().contains("not a robot configuration but a PARSL script")), errors.toString());
    }

    @Test
    void aRunTimeErrorIsShownAtItsLineAndStaysAfterRevalidation() throws Exception {
        Path f = open("rt.xml", snake("10 / ($time - 0.5)"));
        RunOutcome o = runToEnd(2);
        assertEquals(RunOutcome.Status.ERROR, o.status());
        List<Diagnostic> errors = shown(Severity.ERROR);
        assertEquals(1, errors.size(), errors.toString());
        assertEquals(7, errors.get(0).pos().line(), errors.toString());
        assertEquals(f.toString(), errors.get(0).pos().file());
        assertTrue(errors.get(0).message().startsWith("division by zero"), errors.toString());

        int before = ide.validations();
        ide.editor.document().set(ide.editor.document().get() + "\n");
        Gui.pump(() -> ide.validations() > before, "validation of the edited text");
        assertEquals(1, shown(Severity.ERROR).size(), "the run's error vanished when the text was validated again");
    }

    @Test
    void aRobotThatLacksModulesOfTheScriptIsWarnedAbout() throws Exception {
        String big = snake("20").replace("elements=\"0..3\"", "elements=\"0..54\"");
        open("big.xml", big);
        ide.viewBar.select("humanoid");
        RunOutcome o = runToEnd(0.1);
        assertEquals(RunOutcome.Status.COMPLETED, o.status(), o.message());
        List<Diagnostic> warnings = shown(Severity.WARNING);
        assertTrue(warnings.stream().anyMatch(d -> d.message().contains("it has no module 15")), warnings.toString());
    }

    @Test
    void aSimulatorRunEndsWithTheDistanceTravelled() throws Exception {
        open("travel.xml", snake("20"));
        RunOutcome o = runToEnd(0.5);
        assertEquals(RunOutcome.Status.COMPLETED, o.status(), o.message());
        assertTrue(ide.status.message().matches("Run completed at t = 0\\.50 s; the robot travelled \\d+\\.\\d{3} m .*"),
                ide.status.message());
    }
}
