package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.panels.ProblemsView;

/**
 * Issue 23, item 9: the status bar said "No problems" next to problems, a refused Run was only a
 * status-bar line with Problems hidden behind the Run log, the severity column had no header and
 * a bus problem's location was a bare "ttyUSB0". Real widgets under Xvfb.
 */
class StatusAgreesGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    @Test
    void theStatusBarSaysWhatProblemsHoldsAndARefusedRunShowsProblems() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-status"));
        Gui.open(ide, Gui.example("hello-snake.xml"));
        Gui.pump(() -> ide.program() != null, "the example to load");
        Gui.settle();
        assertEquals("No problems", ide.status.message());
        assertEquals("\u2716 0  \u26a0 0", ide.status.problems());

        ide.showRunDiagnostics(List.of(new Diagnostic(Severity.WARNING, SourcePos.origin("bus /dev/ttyUSB0"), "no servo answers")));
        Gui.pump(() -> !ide.problems().shown().isEmpty(), "the run's warning in Problems");
        assertEquals("1 warning: see Problems", ide.status.message(), "'No problems' next to a warning");
        assertEquals("\u2716 0  \u26a0 1", ide.status.problems());
        assertEquals("bus /dev/ttyUSB0", ide.problems().cell(0, 1), "the location names the bus, not a bare 'ttyUSB0'");
        assertEquals("Severity", ide.problems().columnTitle(0));

        String text = ide.editor.document().get();
        int before = ide.validations();
        ide.editor.document().set(text.replace("states=\"up, down\"", "states=\"up, dwn\""));
        Gui.pump(() -> ide.validations() > before, "the broken text to be checked");
        assertTrue(ide.status.message().startsWith("1 error, 1 warning: see Problems"), ide.status.message());
        // Put the Run log in front, as after an earlier run, then press Run: it is refused and Problems comes forward.
        ((org.eclipse.swt.custom.CTabFolder) ide.problems().control().getParent()).setSelection(1);
        assertFalse(ide.bottom.problemsInFront());
        AtomicReference<RunOutcome> refused = new AtomicReference<>();
        ide.runs.run(false, 1, refused::set);
        assertEquals(RunOutcome.Status.ERROR, refused.get().status());
        assertTrue(ide.bottom.problemsInFront(), "a refused Run brings Problems forward");
        assertTrue(ide.status.message().startsWith("Cannot run: fix the 1 error(s)"), ide.status.message());
        assertEquals("\u2716 1  \u26a0 1", ide.status.problems(), "the last run's warning stays until the next run");
        assertTrue(ProblemsView.location(new SourcePos("/home/anna/snake.xml", 3, 4)).equals("snake.xml:3:4"));
    }
}
