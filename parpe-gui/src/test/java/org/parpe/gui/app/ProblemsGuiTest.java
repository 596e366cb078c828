package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.gui.panels.ProblemsView;
import org.parpe.gui.run.Speed;
import org.parpe.gui.run.RunOn;

/**
 * Problems: sorted by file, line, column with a visible Location column; a double-click jumps;
 * run diagnostics survive revalidation of the text and are dropped when a new run starts.
 */
class ProblemsGuiTest {
    private IdeWindow ide;
    private Path script;

    @BeforeEach
    void openWindow() throws Exception {
        ide = new IdeWindow(Gui.display(), new Prefs(Files.createTempDirectory("parpe-problems-test")));
        script = Gui.example("hello-snake.xml").toAbsolutePath().normalize();
        ide.open(script, true);
        Gui.pump(() -> ide.program() != null, "hello-snake.xml to load");
    }

    @AfterEach
    void closeWindow() {
        if (ide != null && !ide.shell.isDisposed()) {
            Gui.endRun(ide);
            ide.shell.dispose();
        }
    }

    private Diagnostic at(Severity s, int line, int column, String message) {
        return new Diagnostic(s, new SourcePos(script.toString(), line, column), message);
    }

    @Test
    void repeatedRunWarningsFoldIntoOneRowWithACount() throws Exception {
        // A bus that keeps failing used to fill Problems with identical warnings.
        Diagnostic again = new Diagnostic(Severity.WARNING, new SourcePos("bus /dev/ttyUSB0", 0, 0),
                "servo 4 had stopped on its watchdog; resuming it");
        ide.showRunDiagnostics(List.of(again, again, at(Severity.WARNING, 3, 5, "overlap"), again));
        Gui.pump(() -> ide.problems().runDiagnostics().size() == 4, "the run diagnostics to be shown");
        ProblemsView view = ide.problems();
        long rows = view.shown().stream().filter(d -> d.message().equals(again.message())).count();
        assertEquals(1, rows, view.shown().toString());
        int row = view.shown().indexOf(again);
        Gui.settle();
        assertEquals(again.message() + "  (\u00d73)", view.cell(row, 2));
    }

    @Test
    void sortedWithAVisibleLocationColumnAndDoubleClickJumps() throws Exception {
        String text = Files.readString(script);
        int before = ide.validations();
        // Two undefined states, the later one first in no particular order of the loader.
        ide.editor.document().set(text.replace("states=\"up, down\"", "states=\"dwn, upp\""));
        Gui.pump(() -> ide.validations() > before, "validation of the edited text");
        ide.showRunDiagnostics(List.of(at(Severity.WARNING, 3, 5, "overlap"), at(Severity.ERROR, 22, 7, "division by zero")));
        Gui.pump(() -> ide.problems().runDiagnostics().size() == 2, "the run diagnostics to be shown");
        ProblemsView view = ide.problems();
        List<Diagnostic> shown = view.shown();
        assertTrue(shown.size() >= 4, "expected 2 load and 2 run diagnostics, got " + shown);
        for (int i = 1; i < shown.size(); i++) {
            SourcePos a = shown.get(i - 1).pos();
            SourcePos b = shown.get(i).pos();
            assertTrue(a.line() < b.line() || a.line() == b.line() && a.column() <= b.column(), "not sorted: " + shown);
        }
        assertEquals("Location", view.columnTitle(1));
        for (int i = 0; i < shown.size(); i++) {
            SourcePos p = shown.get(i).pos();
            assertEquals("hello-snake.xml:" + p.line() + ":" + p.column(), view.cell(i, 1));
        }
        assertEquals("run warning", view.cell(0, 0));

        Gui.settle();
        Table table = (Table) view.control().getChildren()[0];
        int x = 0;
        for (int c = 0; c < 2; c++) {
            TableColumn col = table.getColumn(c);
            x += col.getWidth();
        }
        assertTrue(x <= table.getClientArea().width, "the Location column ends at " + x + " px, beyond the visible "
                + table.getClientArea().width + " px");
        Gui.screenshot(ide.shell, "problems-location-column.png");

        int last = shown.size() - 1;
        table.setSelection(last);
        table.notifyListeners(SWT.DefaultSelection, new Event());
        int caretLine = ide.editor.widget().getLineAtOffset(ide.editor.widget().getCaretOffset()) + 1;
        assertEquals(shown.get(last).pos().line(), caretLine, "double-click did not jump to the problem's line");
    }

    @Test
    void runDiagnosticsSurviveRevalidationAndANewRunClearsThem() {
        Diagnostic fault = at(Severity.ERROR, 12, 7, "bus fault: module 3 did not answer");
        Thread t = new Thread(() -> ide.showRunDiagnostics(List.of(fault)), "test-engine");
        t.start();
        Gui.pump(() -> ide.problems().shown().contains(fault), "the run diagnostic posted from another thread");
        assertTrue(ide.editor.markers().stream().anyMatch(m -> m.diagnostic() == fault), "no marker for the run diagnostic");

        int before = ide.validations();
        ide.editor.document().set(ide.editor.document().get() + "\n");
        Gui.pump(() -> ide.validations() > before, "revalidation");
        assertTrue(ide.problems().shown().contains(fault), "revalidating the text dropped the run diagnostic");

        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(Speed.TIMES_10);
        ide.runs.run(false, -1, null);
        Gui.pump(() -> ide.runs.running(), "the run to start");
        assertFalse(ide.problems().shown().contains(fault), "a new run should drop the last run's diagnostics");
    }
}
