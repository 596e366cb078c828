package org.parpe.cli.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.cli.Cli;
import org.parpe.cli.sim.SimRun;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.RunOutcome;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.Simulator;
import org.parpe.sim.config.RobotConfigs;

/**
 * {@code examples/race-snake-optimised.xml}, written by {@code parpe optimize} from lesson 10's
 * race snake, wins the race against the hand-written script under the race's rules, and stays
 * sane for ten simulated minutes like the other examples (it crawls further than their 100 m
 * box, so it is checked here, without the box's horizontal bounds).
 */
class OptimisedExampleTest {
    private static final Path EXAMPLE = Path.of("../examples/race-snake-optimised.xml");

    @Test
    void theOptimisedGaitBeatsTheHandWrittenOneInTheRace() {
        Cli r = Cli.run("race", "../examples/tutorial/10-race-snake.xml",
                EXAMPLE.toString(), "--sim", "snake:n=8", "--duration", "30");
        assertEquals(0, r.code, r.err);
        List<String> lines = r.out.lines().toList();
        assertTrue(lines.get(1).startsWith("1     ../examples/race-snake-optimised.xml"), r.out);
        assertTrue(lines.get(2).startsWith("2     ../examples/tutorial/10-race-snake.xml"), r.out);
        double optimised = forward(lines.get(1));
        double handWritten = forward(lines.get(2));
        assertTrue(optimised > 3 * handWritten, optimised + " m vs " + handWritten + " m");
    }

    @Test
    void tenSimulatedMinutesStaySane() {
        LoadResult r = ScriptLoader.load(EXAMPLE, Map.of());
        assertNotNull(r.program(), r.diagnostics().toString());
        DiagnosticList d = new DiagnosticList();
        try (Simulator s = new Simulator(RobotConfigs.resolve("snake:n=8", r.program().moduleIds(), d))) {
            assertEquals(RunOutcome.Status.COMPLETED, SimRun.run(r.program(), s, 600, 0.01, x -> { }).status());
            assertFalse(s.hasNaN());
            for (SimBody b : s.snapshot().bodies()) {
                assertTrue(b.position().isFinite() && b.position().z() > -0.05 && b.position().z() < 5,
                        b.part() + " at " + b.position());
            }
            assertTrue(s.metrics().dx() > 50, s.metrics().toJson());
        }
    }

    /** The "forward (m)" column of a ranking line. */
    private static double forward(String line) {
        return Double.parseDouble(line.trim().split("\\s+")[3]);
    }
}
