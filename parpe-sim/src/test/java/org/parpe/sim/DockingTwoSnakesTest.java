package org.parpe.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.sim.internal.Docking;

/**
 * Two six-module snakes that meet and join into one twelve-module snake (issue 35,
 * examples/docking-two-snakes.xml on examples/configs/two-snakes.xml, a configuration with
 * two roots): the rear snake crawls up, the plates latch (dock reads 2 on both), and the
 * joined robot crawls at least 90 % as fast as a twelve-module snake built as one with the
 * same gait.
 */
class DockingTwoSnakesTest {
    private static final Path EXAMPLE = Path.of("../examples/docking-two-snakes.xml");
    private static final String TWO = Path.of("../examples/configs/two-snakes.xml").toString();
    /** The joined robot's crawl is measured from this long after the latch ... */
    private static final double SETTLE = 2;
    /** ... for this long, s. */
    private static final double WINDOW = 20;

    private static Run.Builder builder(String script, String robot, SimTarget[] target) throws Exception {
        LoadResult r = ScriptLoader.loadText(EXAMPLE, script, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        Run.Builder b = Run.builder(r.program(), new RunOptions(0.01, 0, List.of()), new DiagnosticList());
        target[0] = new SimTarget(robot);
        b.attach(target[0]);
        return b;
    }

    @Test
    void theSnakesJoinEndToEndAndCrawlAsOne() throws Exception {
        String script = Files.readString(EXAMPLE);
        SimTarget[] target = new SimTarget[1];
        Run run = builder(script, TWO, target).duration(60).build();
        Simulator sim = target[0].simulator();
        double[] latchedAt = {-1};
        double[] from = {Double.NaN};
        double[] to = {Double.NaN};
        boolean[] stayed = {true};
        run.engine().addObserver((tick, time, commanded) -> {
            boolean both = sim.dock(5, 1) == Docking.LATCHED && sim.dock(6, 0) == Docking.LATCHED;
            if (latchedAt[0] < 0) {
                latchedAt[0] = both ? time : -1;
                return;
            }
            stayed[0] &= both;
            if (Double.isNaN(from[0]) && time >= latchedAt[0] + SETTLE) {
                from[0] = sim.snapshot().centerOfMass().x();
            } else if (time >= latchedAt[0] + SETTLE + WINDOW) {
                to[0] = sim.snapshot().centerOfMass().x();
                run.requestStop();
            }
        });
        run.execute();
        assertTrue(latchedAt[0] > 1, "the rear snake crawls up before the plates latch: at " + latchedAt[0] + " s");
        assertTrue(latchedAt[0] < 10, "the plates latch within 10 s: at " + latchedAt[0] + " s");
        assertTrue(stayed[0], "the plates stay latched while the joined snake crawls");
        double joined = (to[0] - from[0]) / WINDOW;

        // the same crawl on a twelve-module snake built as one: the example's main without its approach
        String asOne = script.replaceAll("<approach exit=\"[^\"]*\"/>", "");
        Run one = builder(asOne, "snake:n=12", target).duration(SETTLE + WINDOW).build();
        Simulator single = target[0].simulator();
        double[] start = {Double.NaN};
        one.engine().addObserver((tick, time, commanded) -> {
            if (Double.isNaN(start[0]) && time >= SETTLE) {
                start[0] = single.snapshot().centerOfMass().x();
            }
        });
        one.execute();
        double built = (single.snapshot().centerOfMass().x() - start[0]) / WINDOW;
        assertTrue(built > 0.01, "the twelve-module snake crawls forwards: " + built + " m/s");
        assertTrue(joined >= 0.9 * built, "joined " + joined + " m/s, built as one " + built + " m/s");
    }

    @Test
    void joiningIsDeterministic() throws Exception {
        assertEquals(trace(), trace());
    }

    private static String trace() throws Exception {
        SimTarget[] target = new SimTarget[1];
        StringWriter out = new StringWriter();
        builder(Files.readString(EXAMPLE), TWO, target).trace(out).duration(6).build().execute();
        assertTrue(out.toString().contains(",2.000000,2.000000\n"), "latched within 6 s");
        return out.toString();
    }
}
