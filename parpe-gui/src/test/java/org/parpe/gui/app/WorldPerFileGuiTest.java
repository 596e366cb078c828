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
import org.parpe.gui.run.RunOn;
import org.parpe.gui.run.Speed;

/**
 * Issue 31, item 2: the World choice was one global setting, so lesson 5's centipede ran inside
 * the race track's walls after a race, for 60 s, and nothing warned. Now the world belongs to the
 * file as the robot does and is remembered across sessions, a script that names its world opens
 * in it, a robot that does not fit the world is a warning in Problems, and a run ended by the
 * world's time limit says so. Real widgets under Xvfb.
 */
class WorldPerFileGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    @Test
    void theWorldBelongsToTheFileAndIsRemembered() throws Exception {
        Path home = Files.createTempDirectory("parpe-world");
        ide = Gui.openIde(home);
        Path race = Gui.example("worlds/race-track.xml").toAbsolutePath().normalize();
        Path a = Gui.example("tutorial/03-hello-snake.xml");
        Path b = Gui.example("tutorial/05-centipede-mirror.xml");
        Gui.open(ide, a);
        ide.viewBar.world().pick(race);
        Gui.open(ide, b);
        assertEquals(WorldPicker.FLAT, ide.viewBar.world().choice(), "lesson 5 keeps its own world");
        assertEquals(null, ide.viewBar.world().world());
        Gui.open(ide, a);
        assertEquals(race.toString(), ide.viewBar.world().choice(), "lesson 3 keeps the race track");
        Gui.screenshot(ide.shell, "world-per-file.png");
        ide.shell.dispose();

        ide = Gui.openIde(home);
        Gui.open(ide, a);
        assertEquals(race.toString(), ide.viewBar.world().choice(), "the world chosen for a file is remembered");
        Gui.open(ide, b);
        assertEquals(WorldPicker.FLAT, ide.viewBar.world().choice());
    }

    @Test
    void aScriptWrittenForAWorldOpensInIt() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-world"));
        Gui.open(ide, Gui.example("tutorial/12-rubble-snake.xml"));
        assertEquals(Gui.example("worlds/rubble.xml").toAbsolutePath().normalize().toString(),
                ide.viewBar.world().choice());
        Gui.open(ide, Gui.example("tutorial/03-hello-snake.xml"));
        assertEquals(WorldPicker.FLAT, ide.viewBar.world().choice(), "a script that names no world: the flat floor");
    }

    @Test
    void aRobotThatDoesNotFitIsWarnedAboutAndTheTimeLimitIsSaid() throws Exception {
        Path home = Files.createTempDirectory("parpe-world");
        ide = Gui.openIde(home);
        // the race track with a one-second time limit, so that the run to the limit is short
        Path track = Files.writeString(home.resolve("race-track-1s.xml"), Files.readString(
                Gui.example("worlds/race-track.xml")).replace("time-limit=\"60\"", "time-limit=\"1\""));
        Gui.open(ide, Gui.example("tutorial/05-centipede-mirror.xml"));
        Gui.pump(() -> ide.program() != null, "lesson 5 to load");
        ide.viewBar.select("centipede");
        ide.viewBar.world().pick(track);
        // said as soon as the world is chosen, before any run
        Gui.pump(() -> ide.status.message().startsWith("Robot centipede does not fit the world race-track-1s.xml: it starts "),
                "the status to say the centipede does not fit: " + ide.status.message());
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(Speed.MAX);
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        ide.runs.run(false, -1, outcome::set);
        Gui.pump(() -> outcome.get() != null, "lesson 5 on the one-second race track");
        Gui.pump(() -> ide.problems().shown().stream().anyMatch(d -> d.severity() == Severity.WARNING),
                "the warning in Problems: " + ide.problems().shown());
        List<String> warnings = ide.problems().shown().stream().filter(d -> d.severity() == Severity.WARNING)
                .map(Diagnostic::message).toList();
        assertTrue(warnings.stream().anyMatch(m -> m.startsWith("the robot does not fit the world race-track-1s.xml: ")),
                warnings.toString());
        // in a world the score comes first (what a teacher records), then how the run ended
        assertTrue(ide.status.message().contains("run ended at the world's time limit, t = 1.00 s"),
                ide.status.message());
    }
}
