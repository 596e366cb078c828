package org.parpe.gui.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.sim.sweep.SweepRow;

/**
 * Lesson 11's sweep made in the IDE's Sweep dialog, as the lesson tells (Vary bend and period,
 * hold the phase at 0.125), names the same best run as the lesson's {@code parpe sweep} line
 * (which the command line's Lesson11SweepTest checks), numbered as the CSV numbers it, and that
 * run did not fall over (issue 23, items 1 and 13: the IDE crowned a fallen run, numbered runs
 * from 1 and could not hold a parameter at a value).
 */
class Lesson11IdeSweepTest {
    private Shell window;
    private SweepDialog dialog;

    @AfterEach
    void close() {
        Ui.close(dialog);
        if (window != null) {
            window.dispose();
        }
    }

    @Test
    void theLessonsSweepInTheIdeNamesTheCommandLinesUprightBestRun() throws Exception {
        String lesson = Files.readString(Path.of("../docs/tutorial/11-optimise.md"));
        Matcher said = Pattern.compile("\nparpe: best forward-speed ([0-9.]+) with bend=(\\S+) period=(\\S+) \\(run (\\d+)\\)\n")
                .matcher(lesson);
        assertTrue(said.find(), "lesson 11 shows the best run");
        Path file = Path.of(System.getProperty("parpe.examples", "../examples"), "tutorial/10-race-snake.xml")
                .toAbsolutePath().normalize();
        window = new Shell(Ui.display());
        window.setLayout(new FillLayout());
        ParslEditor editor = new ParslEditor(window);
        editor.setText(Files.readString(file));
        window.open();
        dialog = SweepDialog.open(new SweepHost(window, editor, new ScriptDocument(window.getDisplay(), editor.document(), () -> file), () -> "auto", () -> null, d -> { }));
        dialog.setJobs(2);
        dialog.setDuration("30");
        Ui.vary(dialog, "bend", "10", "70", 7);
        Ui.vary(dialog, "period", "1", "2", 3);
        SweepTab.Line phase = dialog.sweepTab().line("phase");
        phase.hold().setText("0.125");
        Ui.click(dialog.startButton());
        assertTrue(dialog.running(), dialog.message());
        Ui.pump(() -> !dialog.running(), "lesson 11's 21 runs");
        List<SweepRow> rows = dialog.results().rows();
        assertEquals(21, rows.size(), dialog.message());
        assertTrue(rows.stream().allMatch(r -> r.values().size() == 2), "only bend and period vary");
        assertTrue(rows.stream().anyMatch(SweepRow::fell), "some runs of lesson 11 fall over");
        SweepRow best = dialog.results().best();
        assertNotNull(best, dialog.message());
        assertFalse(best.fell(), "the best run did not fall over");
        assertEquals("Finished 21 runs. Best: run " + said.group(4) + ", bend = " + said.group(2) + ", period = "
                + said.group(3) + ": forward speed (m/s) " + said.group(1), dialog.message());
        // The run column of the table says the same number as the CSV's.
        assertEquals(said.group(4), dialog.table().cell(Integer.parseInt(said.group(4)), 0));
        Ui.screenshot(dialog.shell(), "sweep-dialog-lesson11.png");
    }
}
