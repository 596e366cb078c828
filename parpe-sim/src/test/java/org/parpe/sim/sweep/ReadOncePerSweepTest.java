package org.parpe.sim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.text.Message;

/**
 * Issue 19, item 8: a sweep reads its script, includes and robot file once, when it starts, and
 * binds them to each run's values; a value that changes the robot's modules still gets a robot
 * with those modules. Before, every run (and every worker) read the files again, so deleting an
 * include during a sweep made the later runs fail.
 */
class ReadOncePerSweepTest {
    private static final String MAIN = """
            <program>
              <robot file="body.xml"/>
              <parameters>
                <last value="5" min="3" max="7"/>
                <bend value="30" min="0" max="60"/>
              </parameters>
              <include file="gait.xml"/>
              <main><go/></main>
            </program>
            """;
    private static final String BODY = """
            <robot><structure><body elements="0..last"/></structure></robot>
            """;
    private static final String GAIT = """
            <program>
              <behaviors><go><wave group="body" phase="0.2" period="1.5"/></go></behaviors>
              <automata><wave states="up, down"/></automata>
              <states><up angles="bend" interp="smooth"/><down angles="-bend" interp="smooth"/></states>
            </program>
            """;

    @TempDir
    Path dir;

    private Evaluator load() throws Exception {
        Path main = dir.resolve("snake-read-once.xml");
        Files.writeString(main, MAIN);
        Files.writeString(dir.resolve("body.xml"), BODY);
        Files.writeString(dir.resolve("gait.xml"), GAIT);
        return Evaluator.load(new Evaluator.Settings(main, MAIN, Map.of(), "auto", 1.0, 0.01, 90));
    }

    private static List<SweepRow> rows(Sweep sweep, int jobs) {
        SweepResult r = sweep.run(jobs, new SweepListener() {
        }, new Cancellation());
        return r.rows();
    }

    @Test
    void filesChangedAfterTheSweepStartedDoNotReachItsRuns() throws Exception {
        Evaluator ev = load();
        Sweep sweep = new Sweep(ev, SweepSpec.grid(List.of(VarySpec.parse("last=3,7", ev.parameters()),
                VarySpec.parse("bend=20,40", ev.parameters())), 1, 3));
        Files.delete(dir.resolve("gait.xml"));
        Files.writeString(dir.resolve("body.xml"), "<robot><structure><body elements=\"0\"/></structure></robot>");
        List<SweepRow> two = rows(sweep, 2);
        assertEquals(4, two.size());
        for (SweepRow r : two) {
            assertEquals(Message.EMPTY, r.error(), r.values().toString());
        }
        assertEquals(two, rows(sweep, 1), "the rows do not depend on --jobs");
    }

    @Test
    void aValueThatChangesTheModulesGetsARobotWithThoseModules() throws Exception {
        Evaluator ev = load();
        Sweep sweep = new Sweep(ev, SweepSpec.grid(List.of(VarySpec.parse("last=3,7,3", ev.parameters())), 1, 3));
        List<SweepRow> rows = rows(sweep, 2);
        List<String> errors = new ArrayList<>();
        rows.forEach(r -> errors.add(r.error().toString()));
        assertEquals(List.of("", "", ""), errors);
        // a 4-module and an 8-module snake move differently; the 4-module one again as the first time
        assertNotEquals(rows.get(0).distance(), rows.get(1).distance());
        assertEquals(rows.get(0).distance(), rows.get(2).distance());
        // and each as a script loaded with that value from the start
        for (SweepRow r : rows) {
            Path main = dir.resolve("snake-read-once.xml");
            Evaluator alone = Evaluator.load(new Evaluator.Settings(main, MAIN, r.values(), "auto", 1.0, 0.01, 90));
            SweepRow expected = alone.run(new Point(0, 0, 0, Map.of(), r.point().seed()), new Cancellation());
            assertEquals(expected.distance(), r.distance(), r.values().toString());
            assertEquals(expected.jointTravelDeg(), r.jointTravelDeg(), r.values().toString());
        }
    }

    /** The bridge to a lane: its evaluator and ODE4j are its own, the bridge's classes are the application's. */
    @Test
    void aLaneHasItsOwnSimulatorAndSharesTheBridge() throws Exception {
        Evaluator ev = load();
        ClassLoader lane = Lanes.acquire();
        try {
            PointRunner far = Lanes.runnerIn(lane, new RunSetup(
                    org.parpe.core.load.ScriptLoader.read(ev.script(), ev.text()), ev.text(), Map.of(), "auto", 1.0,
                    0.01, 90, null));
            assertTrue(far != null, "the test's class path has the simulator");
            assertSame(lane, far.getClass().getClassLoader());
            assertNotSame(Evaluator.class, far.getClass());
            assertNotSame(Class.forName("org.ode4j.ode.OdeHelper"), Class.forName("org.ode4j.ode.OdeHelper", false, lane));
            for (Class<?> shared : List.of(PointRunner.class, RunSetup.class, Point.class, SweepRow.class,
                    Cancellation.class, org.parpe.core.load.ParsedScript.class)) {
                assertSame(shared, Class.forName(shared.getName(), false, lane), shared.getName());
            }
            Point p = new Point(0, 0, 0, Map.of("bend", 25.0), 4);
            assertEquals(ev.run(p, new Cancellation()), far.run(p, new Cancellation()));
        } finally {
            Lanes.release(lane);
        }
    }
}
