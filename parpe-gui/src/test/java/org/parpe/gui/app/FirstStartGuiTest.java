package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import org.parpe.gui.help.HelpText;
import org.parpe.gui.help.QuickReference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
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

    private static long tutorials() {
        return Arrays.stream(Gui.display().getShells()).filter(s -> !s.isDisposed() && "PARPE tutorial".equals(s.getText()))
                .count();
    }

    @Test
    void theFirstStartOpensTheTutorialAndTheNextDoesNot() throws Exception {
        Path home = Files.createTempDirectory("parpe-first");
        ide = new IdeWindow(Gui.display(), new Prefs(home));
        ide.open(null, false);
        Gui.settle();
        assertEquals(1, tutorials(), "the tutorial is offered at the very first start");
        assertTrue(ide.editor().document().get().contains("Help > Tutorial"), "the new script points to the tutorial");
        ide.shell().dispose();
        assertEquals(0, tutorials(), "the tutorial closes with the IDE");
        ide = new IdeWindow(Gui.display(), new Prefs(home));
        ide.open(null, false);
        Gui.settle();
        assertEquals(0, tutorials(), "only the first start opens it");
    }

    @Test
    void anEmergencyStopIsNotReportedAsAnOrdinaryStop() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-estop"));
        Gui.open(ide, Gui.example("hello-snake.xml"));
        Gui.pump(() -> ide.program() != null, "the example to load");
        ide.toolbar().setSpeed(Speed.REAL_TIME);
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        ide.runs().run(false, -1, outcome::set);
        Gui.pump(() -> ide.runs().controller().status() != null, "the run to start");
        ide.runs().emergencyStop();
        Gui.pump(() -> outcome.get() != null, "the emergency stop to end the run");
        assertTrue(ide.status().message().startsWith("Emergency stop at t = "), ide.status().message());
        outcome.set(null);
        ide.runs().run(false, -1, outcome::set);
        Gui.pump(() -> ide.runs().controller().status() != null && ide.runs().running(), "the next run to start");
        ide.runs().stop();
        Gui.pump(() -> outcome.get() != null, "Stop to end the run");
        assertTrue(ide.status().message().startsWith("Run stopped at t = "), ide.status().message());
    }

    @Test
    void saveCsvStartsBesideTheScriptOrInDocuments() throws Exception {
        Path home = Files.createTempDirectory("parpe-home");
        Path work = Files.createDirectories(home.resolve("work"));
        assertEquals(work, org.parpe.gui.sweep.SweepDialogAccess.csvFolder(work.resolve("a.xml"), home));
        Files.createDirectories(home.resolve("Documents"));
        assertEquals(home.resolve("Documents"), org.parpe.gui.sweep.SweepDialogAccess.csvFolder(home.resolve("gone/none.xml"), home));
    }

    @Test
    void theQuickReferenceIsInTheFixedWidthFontSoItsColumnsLineUp() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-help"));
        org.eclipse.swt.widgets.Shell help = QuickReference.open(ide.shell());
        try {
            org.eclipse.swt.widgets.Text t = Arrays.stream(help.getChildren()).filter(c -> c instanceof org.eclipse.swt.widgets.Text)
                    .map(c -> (org.eclipse.swt.widgets.Text) c).findFirst().orElseThrow();
            assertEquals(HelpText.QUICK_REFERENCE, t.getText());
            assertEquals(org.eclipse.jface.resource.JFaceResources.getTextFont(), t.getFont());
            org.eclipse.swt.graphics.GC gc = new org.eclipse.swt.graphics.GC(t);
            try {
                assertEquals(gc.textExtent("iiii").x, gc.textExtent("MMMM").x, "the font is not fixed-width");
            } finally {
                gc.dispose();
            }
        } finally {
            help.dispose();
        }
    }
}
