package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import org.parpe.gui.help.HelpText;
import org.parpe.gui.help.QuickReference;
import org.parpe.gui.automation.Screenshot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.Speed;

/**
 * Issue 23, item 15: nothing offered the tutorial to a student who has never programmed, and the
 * emergency stop printed the same line as a normal stop. Real widgets under Xvfb.
 */
class FirstStartGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    /** The tutorials open: windows of their own, and the one docked in the IDE (where the screen has no room beside it). */
    private long tutorials() {
        return Arrays.stream(Gui.display().getShells()).filter(s -> !s.isDisposed() && "PARPE tutorial".equals(s.getText()))
                .count() + (ide.shell.isDisposed() || ide.tutorialDock.tutorial() == null ? 0 : 1);
    }

    @Test
    void theFirstStartOpensTheTutorialAndTheNextDoesNot() throws Exception {
        Path home = Files.createTempDirectory("parpe-first");
        ide = new IdeWindow(Gui.display(), new Prefs(home));
        ide.open(null, false);
        Gui.settle();
        assertEquals(1, tutorials(), "the tutorial is offered at the very first start");
        assertTrue(ide.editor.document().get().contains("Help > Tutorial"), "the new script points to the tutorial");
        ide.shell.dispose();
        assertEquals(0, tutorials(), "the tutorial closes with the IDE");
        ide = new IdeWindow(Gui.display(), new Prefs(home));
        ide.open(null, false);
        Gui.settle();
        assertEquals(0, tutorials(), "only the first start opens it");
        org.eclipse.swt.widgets.MenuItem atStart = menuItem(ide.shell.getMenuBar(), "Open the Tutorial at Every Start");
        assertTrue(!atStart.getSelection(), "off unless asked for");
        atStart.setSelection(true);
        atStart.notifyListeners(org.eclipse.swt.SWT.Selection, new org.eclipse.swt.widgets.Event());
        ide.shell.dispose();
        ide = new IdeWindow(Gui.display(), new Prefs(home));
        ide.open(null, false);
        Gui.settle();
        assertEquals(1, tutorials(), "the preference opens it at every start");
        assertTrue(menuItem(ide.shell.getMenuBar(), "Open the Tutorial at Every Start").getSelection());
    }

    private static org.eclipse.swt.widgets.MenuItem menuItem(org.eclipse.swt.widgets.Menu menu, String text) {
        for (org.eclipse.swt.widgets.MenuItem it : menu.getItems()) {
            if (it.getText().replace("&", "").equals(text)) {
                return it;
            }
            if (it.getMenu() != null) {
                org.eclipse.swt.widgets.MenuItem in = menuItem(it.getMenu(), text);
                if (in != null) {
                    return in;
                }
            }
        }
        return null;
    }

    @Test
    void anEmergencyStopIsNotReportedAsAnOrdinaryStop() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-estop"));
        Gui.open(ide, Gui.example("hello-snake.xml"));
        Gui.pump(() -> ide.program() != null, "the example to load");
        ide.toolbar.setSpeed(Speed.REAL_TIME);
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        ide.runs.run(false, -1, outcome::set);
        Gui.pump(() -> ide.runs.controller().status() != null, "the run to start");
        ide.runs.emergencyStop();
        Gui.pump(() -> outcome.get() != null, "the emergency stop to end the run");
        assertTrue(ide.status.message().startsWith("Emergency stop at t = "), ide.status.message());
        outcome.set(null);
        ide.runs.run(false, -1, outcome::set);
        Gui.pump(() -> ide.runs.controller().status() != null && ide.runs.running(), "the next run to start");
        ide.runs.stop();
        Gui.pump(() -> outcome.get() != null, "Stop to end the run");
        assertTrue(ide.status.message().startsWith("Run stopped at t = "), ide.status.message());
    }

    /**
     * Help's quick reference was a message box with space-aligned columns in a proportional font:
     * now a table whose columns show each cell whole, with the examples in the fixed-width font.
     */
    @Test
    void theQuickReferenceIsATableWhoseColumnsShowEveryCell() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-help"));
        org.eclipse.swt.widgets.Shell help = QuickReference.open(ide.shell);
        try {
            Gui.settle();
            org.eclipse.swt.widgets.Table t = Arrays.stream(help.getChildren()).filter(c -> c instanceof org.eclipse.swt.widgets.Table)
                    .map(c -> (org.eclipse.swt.widgets.Table) c).findFirst().orElseThrow(() -> new AssertionError("no table"));
            assertTrue(t.getHeaderVisible());
            assertEquals(List.of("Section", "What it holds", "Example"),
                    Arrays.stream(t.getColumns()).map(org.eclipse.swt.widgets.TableColumn::getText).toList());
            assertEquals(HelpText.sections().length, t.getItemCount());
            for (int r = 0; r < t.getItemCount(); r++) {
                org.eclipse.swt.widgets.TableItem item = t.getItem(r);
                for (int c = 0; c < 3; c++) {
                    assertEquals(HelpText.sections()[r][c], item.getText(c));
                    org.eclipse.swt.graphics.GC gc = new org.eclipse.swt.graphics.GC(t);
                    try {
                        gc.setFont(item.getFont(c));
                        int need = gc.textExtent(item.getText(c)).x;
                        assertTrue(t.getColumn(c).getWidth() >= need, "column " + c + " (" + t.getColumn(c).getWidth() + " px) cuts '" + item.getText(c) + "' (" + need + " px)");
                    } finally {
                        gc.dispose();
                    }
                }
                assertEquals(org.eclipse.jface.resource.JFaceResources.getTextFont(), item.getFont(2), "examples are code");
            }
            assertTrue(help.getBounds().width >= Arrays.stream(t.getColumns()).mapToInt(org.eclipse.swt.widgets.TableColumn::getWidth).sum(),
                    "the window shows the whole table: " + help.getBounds());
            Gui.settle();
            java.nio.file.Path shots = java.nio.file.Path.of(System.getProperty("parpe.artefacts", "target/gui-test-artefacts"));
            Files.createDirectories(shots);
            Screenshot.save(help, shots.resolve("quick-reference.png"));
        } finally {
            help.dispose();
        }
    }
}
