package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Rectangle;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.RunOn;
import org.parpe.gui.run.Speed;

/**
 * Issue 31, item 2: at the end of an IDE run in a world the score was gone (the 3D line dropped
 * it, the status bar cut it off, the Run log did not wrap), yet teachers.md tells teachers to
 * record it. Now the status bar starts with the score, the Run log wraps and is in front with the
 * score and its parts on a line of their own, and the 3D line keeps the final score. Real widgets
 * at 1366×768.
 */
class ScoreAfterRunGuiTest {
    @TempDir
    static Path home;
    static IdeWindow ide;

    @BeforeAll
    static void open() {
        ide = Gui.openIde(home, 1366, 768);
    }

    @AfterAll
    static void close() {
        Gui.closeIde(ide);
    }

    @Test
    void theFinalScoreAndItsPartsAreReadableAfterTheRun() throws Exception {
        int checked = ide.validations();
        Gui.open(ide, Gui.example("worlds/race-track-snake.xml"));
        // the opened text's check, which says "No problems" in the status bar, comes before the run, not after it
        Gui.pump(() -> ide.validations() > checked && ide.program() != null, "the script's check");
        ide.viewBar.world().choose(Gui.example("worlds/race-track.xml"));
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(Speed.MAX);
        AtomicReference<RunOutcome> end = new AtomicReference<>();
        ide.runs.run(false, 12, end::set);
        Gui.pump(() -> end.get() != null, "the run in the race track");
        Gui.settle();

        String status = ide.status.message();
        assertTrue(status.matches("Score \\d+\\.\\d \\(.+\\).*"), "the status bar starts with the score and its parts: " + status);

        StyledText log = ide.runLog();
        assertTrue(ide.bottom.runLogInFront(), "the Run log is in front after a run with a score");
        assertTrue(log.getWordWrap(), "the Run log wraps: nobody scrolls sideways for the score");
        assertTrue(log.getHorizontalBar() == null || !log.getHorizontalBar().isVisible(), "no sideways scroll bar");
        String last = log.getLine(log.getLineCount() - 2); // the text ends with a line break
        assertTrue(last.matches(".*Score \\d+\\.\\d: .*path \\d+\\.\\d\\d m.*"), "the log's last line is the score and its parts: " + last);
        // the score's line is in sight, not scrolled away: its end lies inside the log's client area
        int at = log.getText().lastIndexOf("Score");
        Rectangle area = log.getClientArea();
        var p = log.getLocationAtOffset(at + "Score".length());
        assertTrue(area.contains(p), "the score is in sight in the Run log: " + p + " in " + area);

        String hud = ide.view.hudText();
        assertTrue(hud.contains("final score "), "the 3D line keeps the final score after the run: " + hud);
        GC gc = new GC(ide.view.control());
        try {
            assertFalse(gc.textExtent(hud).x > ide.view.control().getSize().x, "the 3D line fits the view: " + hud);
        } finally {
            gc.dispose();
        }
        Gui.screenshot(ide.shell, "score-after-run-1366x768.png");
    }
}
