package org.parpe.gui.app;


import org.parpe.gui.files.Autosave;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.editor.ProblemAnnotation;
import org.parpe.gui.run.Speed;
import org.parpe.gui.run.RunOn;

/**
 * The IDE for real on an X display (Xvfb in CI): open an example, run it in the simulator,
 * steer it with a control, stop it; a broken script gets a marker at the right line. Every wait
 * is bounded; screenshots are kept under {@code target/gui-test-artefacts} as evidence.
 */
class IdeGuiTest {
    private static IdeWindow ide;

    @BeforeAll
    static void openWindow() throws Exception {
        Path home = Files.createTempDirectory("parpe-gui-test");
        ide = Gui.openIde(home);
    }

    @AfterAll
    static void closeWindow() {
        if (ide != null && !ide.shell.isDisposed()) {
            Gui.endRun(ide);
            ide.shell.dispose();
        }
    }

    private static double engineTime() {
        var st = ide.runs.controller().status();
        return st == null ? -1 : st.time();
    }

    @Test
    void runsAnExampleInTheSimulatorAndSteersItWithAControl() throws Exception {
        Gui.open(ide, Gui.example("teleop-dirwave.xml"));
        int before = ide.validations();
        Gui.pump(() -> ide.validations() > before && ide.program() != null, "teleop-dirwave.xml to load");
        assertEquals(0, ide.problems().errorCount(), "example has errors: " + ide.problems().shown());
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(Speed.TIMES_10);
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        ide.runs.run(false, -1, outcome::set);
        Gui.pump(() -> engineTime() >= 1.0, "1 s of simulated time");
        assertFalse(ide.runs.driven().isEmpty(), "the wave should drive modules while direction = forward");
        // The view draws on its own timer (about 30 frames a second): at x10 the engine may pass 1 s first.
        Gui.pump(() -> ide.view.lastSnapshot() != null, "the 3D view to draw the robot");
        assertNotNull(ide.view.lastSnapshot(), "the 3D view has drawn no robot");
        assertFalse(ide.view.lastSnapshot().bodies().isEmpty());

        assertTrue(ide.controls.set("direction", "stop"), "no 'direction' radio control in the panel");
        double changedAt = engineTime();
        Gui.pump(() -> engineTime() > changedAt + 0.2 && ide.runs.driven().isEmpty(),
                "the modules to stop being driven after direction = stop");
        assertTrue(ide.controls.set("direction", "backward"));
        Gui.pump(() -> engineTime() >= 3.0 && !ide.runs.driven().isEmpty(), "3 s of simulated time, driven backwards");
        assertEquals(0, ide.problems().errorCount(), "control changes refused: " + ide.problems().shown());
        Gui.screenshot(ide.shell, "teleop-running.png");

        ide.runs.stop();
        Gui.pump(() -> outcome.get() != null, "the run to stop");
        assertEquals(RunOutcome.Status.STOPPED, outcome.get().status(), outcome.get().message());
        assertTrue(outcome.get().time() >= 3.0);
        assertFalse(ide.runs.running());
    }

    @Test
    void aBrokenScriptShowsAnErrorMarkerAtTheRightLine() throws Exception {
        Gui.open(ide, Gui.example("hello-snake.xml"));
        String text = Files.readString(Gui.example("hello-snake.xml"));
        List<String> lines = List.of(text.split("\n", -1));
        int line = -1;
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).contains("states=\"up, down\"")) {
                line = i + 1;
            }
        }
        assertTrue(line > 0, "hello-snake.xml has no 'states=\"up, down\"' line to break");
        int before = ide.validations();
        ide.editor.document().set(text.replace("states=\"up, down\"", "states=\"up, dwn\""));
        Gui.pump(() -> ide.validations() > before, "validation of the edited text");
        assertTrue(ide.problems().errorCount() > 0, "no error for an undefined state");
        List<ProblemAnnotation> marks = ide.editor.markers();
        assertFalse(marks.isEmpty(), "no marker in the editor");
        int expected = line;
        assertTrue(marks.stream().anyMatch(m -> m.isError() && ide.editor.lineOf(m) == expected),
                "no error marker on line " + expected + "; markers on lines "
                        + marks.stream().map(ide.editor::lineOf).toList());
        assertTrue(ide.files.dirty(), "an edited file should be marked dirty");
        Gui.screenshot(ide.shell, "broken-script.png");

        AtomicReference<RunOutcome> refused = new AtomicReference<>();
        ide.runs.run(false, 1, refused::set);
        assertNotNull(refused.get(), "Run should refuse a script with errors at once");
        assertEquals(RunOutcome.Status.ERROR, refused.get().status());
        assertFalse(ide.runs.running());
    }

    /** On its own text, not the one the broken-script test leaves (no test depends on another's order). */
    @Test
    void unsavedTextIsKeptForRecovery() throws Exception {
        Gui.open(ide, Gui.example("hello-snake.xml"));
        String text = Files.readString(Gui.example("hello-snake.xml"));
        ide.editor.document().set(text.replace("states=\"up, down\"", "states=\"up, dwn\""));
        assertTrue(ide.files.dirty(), "an edited file should be marked dirty");
        ide.files.autosaveNow();
        List<Autosave.Copy> copies = ide.files.autosave().own();
        assertEquals(1, copies.size(), "expected one autosave copy of the unsaved text: " + copies);
        assertTrue(copies.get(0).text().contains("up, dwn"));
        assertEquals(Gui.example("hello-snake.xml").toAbsolutePath().normalize(), copies.get(0).file());
    }
}
