package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.Speed;
import org.parpe.gui.run.RunOn;

/**
 * Issue 23, item 3: after one run on the humanoid every snake lesson ran on the humanoid and fell,
 * with "No problems"; yesterday's hardware target made today's lesson fail. Now the robot and the
 * target belong to the file (auto and the simulator by default), a new session starts on the
 * simulator, and a run on a robot that does not fit the script, or that falls over, is warned
 * about in Problems and the status bar. Real widgets under Xvfb.
 */
class RunChoicesGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    @Test
    void robotAndTargetArePerFileAndANewSessionStartsOnTheSimulator() throws Exception {
        Path home = Files.createTempDirectory("parpe-choices");
        ide = Gui.openIde(home);
        Path humanoidLesson = Gui.example("standup-walk.xml");
        Path snakeLesson = Gui.example("tutorial/03-hello-snake.xml");
        Gui.open(ide, humanoidLesson);
        ide.viewBar.select("humanoid");
        ide.toolbar.chooseTarget(RunOn.HARDWARE);
        Gui.open(ide, snakeLesson);
        assertEquals("auto", ide.robotChoice(), "the snake lesson keeps its own robot");
        assertEquals(RunOn.SIMULATOR, ide.toolbar.target(), "the snake lesson keeps its own target");
        Gui.open(ide, humanoidLesson);
        assertEquals("humanoid", ide.robotChoice());
        assertEquals(RunOn.HARDWARE, ide.toolbar.target());
        ide.shell.dispose();

        ide = Gui.openIde(home);
        Gui.open(ide, humanoidLesson);
        assertEquals("humanoid", ide.robotChoice(), "the robot chosen for a file is remembered");
        assertEquals(RunOn.SIMULATOR, ide.toolbar.target(), "every session starts on the simulator");
    }

    @Test
    void aRobotThatDoesNotFitAndFallsOverIsWarnedAbout() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-choices"));
        Gui.open(ide, Gui.example("tutorial/03-hello-snake.xml"));
        Gui.pump(() -> ide.program() != null, "the lesson to load");
        ide.viewBar.select("humanoid");
        ide.toolbar.setSpeed(Speed.MAX);
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        ide.runs.run(false, 5, outcome::set);
        Gui.pump(() -> outcome.get() != null, "5 s of the snake lesson on the humanoid");
        // Both warnings reach Problems through the event queue.
        Gui.pump(() -> ide.problems().shown().stream().filter(d -> d.severity() == Severity.WARNING).count() >= 2,
                "the two warnings in Problems: " + ide.problems().shown());
        List<String> warnings = ide.problems().shown().stream().filter(d -> d.severity() == Severity.WARNING)
                .map(Diagnostic::message).toList();
        assertTrue(warnings.stream().anyMatch(m -> m.startsWith("this script is written for the snake")), warnings.toString());
        assertTrue(warnings.stream().anyMatch(m -> m.startsWith("the robot fell over (it tilted ")), warnings + " " + ide.status.message());
        assertTrue(ide.status.message().contains("it fell over (see Problems)"), ide.status.message());
    }
}
