package org.parpe.cli.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.SimMetrics;
import org.parpe.sim.Simulator;
import org.parpe.sim.config.RobotConfigs;

/** The example scripts on their simulated robots: the gaits move them, and long runs stay sane. */
class ExamplesOnSimulatorTest {
    private static final Path EXAMPLES = Path.of("..", "examples");

    private static Program program(String file) {
        LoadResult r = ScriptLoader.load(EXAMPLES.resolve(file), Map.of());
        assertNotNull(r.program(), r.diagnostics().toString());
        return r.program();
    }

    private static Simulator simulator(String spec, Program p) {
        DiagnosticList d = new DiagnosticList();
        Simulator s = new Simulator(RobotConfigs.resolve(spec, p.moduleIds(), d));
        assertFalse(d.hasErrors(), d.all().toString());
        return s;
    }

    private static SimMetrics run(String file, String spec, double seconds) {
        Program p = program(file);
        try (Simulator s = simulator(spec, p)) {
            assertEquals(RunOutcome.Status.COMPLETED, SimRun.run(p, s, seconds, 0.01, d -> { }).status());
            return s.metrics();
        }
    }

    @Test
    void helloSnakeCrawls() {
        SimMetrics m = run("hello-snake.xml", "snake", 20);
        assertTrue(m.distance() >= 0.1, m.toJson());
    }

    @Test
    void theWheelRolls() {
        SimMetrics m = run("wheel.xml", "wheel", 20);
        assertTrue(m.distance() >= 0.3, m.toJson());
    }

    /**
     * The paper's Fig. 7 wheel gait rolls the Fig. 6 wheel forwards (+x, as every standard robot
     * faces), and rolling is not falling: its hub turns over and over, its axle stays level.
     */
    @Test
    void theFig7WheelRollsForwardsAndDoesNotFall() {
        SimMetrics m = run("wheel.xml", "wheel", 20);
        assertTrue(m.dx() >= 0.3, m.toJson());
        assertFalse(m.fell(), m.toJson());
        assertTrue(m.maxTiltDeg() < 45, m.toJson());
    }

    /** The rolling loop is judged by its hinge axis, which rolling leaves level: it does not fall. */
    @Test
    void theRollingLoopDoesNotFall() {
        SimMetrics m = run("param-loop.xml", "loop", 20);
        assertTrue(m.distance() >= 0.3, m.toJson());
        assertFalse(m.fell(), m.toJson());
    }

    /** A wheel stood leaning 30 degrees falls flat: its axle tips, and that is falling. */
    @Test
    void aLeaningWheelFallsOver(@org.junit.jupiter.api.io.TempDir Path dir) throws java.io.IOException {
        String config = java.nio.file.Files.readString(EXAMPLES.resolve("configs/wheel6.xml"))
                .replace("roll=\"90\"", "roll=\"60\"");
        Path leaning = java.nio.file.Files.writeString(dir.resolve("leaning.xml"), config);
        SimMetrics m = run("wheel.xml", leaning.toString(), 10);
        assertTrue(m.fell(), m.toJson());
    }

    @Test
    void theCentipedeWalksForwards() {
        SimMetrics m = run("centipede-walk.xml", "centipede", 20);
        assertTrue(m.dx() >= 0.1, m.toJson());
    }

    /**
     * Issue 33 item 6: the paper's frog-like robot hops forwards (+x) on its own configuration,
     * and stays on its feet.
     */
    @Test
    void theFrogHopsForwards() {
        SimMetrics m = run("frog-hop.xml", "../examples/configs/frog.xml", 20);
        assertTrue(m.dx() >= 0.3, m.toJson());
        assertTrue(Math.abs(m.dy()) < m.dx() / 3, "it hops straight: " + m.toJson());
        assertFalse(m.fell(), m.toJson());
    }

    /**
     * Issue 33 item 6: the flipping/rolling ring goes over side after side, forwards, and
     * flipping is not falling (it is judged by its axle, which stays level).
     */
    @Test
    void theFlipperTumblesForwards() {
        SimMetrics m = run("flipper-tumble.xml", "../examples/configs/flipper.xml", 20);
        assertTrue(m.dx() >= 0.4, m.toJson());
        assertFalse(m.fell(), m.toJson());
    }

    /**
     * Issue 33 item 6: the Fig. 2 humanoid (the paper, Fig. 2: "a 15-module humanoid") does what
     * humanoid-wave.xml's comment says: it crouches and stays up for 10 s (tilt well under 90
     * degrees), its knees hold the crouch, its right arm is raised above its left, and its elbow
     * swings out and in by the wave's 40 degrees (commanded +40 at 9.6 s, -40 at 9.0 s).
     */
    @Test
    void theHumanoidCrouchesStaysUpAndWaves() {
        SimMetrics m = run("humanoid-wave.xml", "../examples/configs/humanoid15.xml", 10);
        assertFalse(m.fell(), m.toJson());
        assertTrue(m.maxTiltDeg() < 15, m.toJson());
        double[] in = humanoidAt(9.0);
        double[] out = humanoidAt(9.6);
        assertEquals(-40, in[0], 5, "knee 2 holds the crouch");
        assertEquals(60, in[1], 5, "right shoulder 12 raised");
        assertTrue(in[2] < -30 && out[2] > 30, "elbow 14 waves: " + in[2] + " then " + out[2]);
        assertTrue(in[3] > in[4] + 0.05, "the right hand is above the left: " + in[3] + " vs " + in[4]);
    }

    /** After {@code seconds} of humanoid-wave.xml: knee 2, shoulder 12, elbow 14 (degrees), right and left hand z (m). */
    private static double[] humanoidAt(double seconds) {
        Program p = program("humanoid-wave.xml");
        try (Simulator s = simulator("../examples/configs/humanoid15.xml", p)) {
            SimRun.run(p, s, seconds, 0.01, d -> { });
            SensorTable t = s.readings();
            double[] r = new double[5];
            int[] ids = {2, 12, 14};
            for (int i = 0; i < ids.length; i++) {
                r[i] = t.get(t.indexOf(ids[i]), Channel.ANGLE);
            }
            for (SimBody b : s.snapshot().bodies()) {
                r[3] = b.part().equals("Rarm2") ? b.position().z() : r[3];
                r[4] = b.part().equals("Larm2") ? b.position().z() : r[4];
            }
            return r;
        }
    }

    @ParameterizedTest
    @CsvSource({"frog-hop.xml, ../examples/configs/frog.xml", "flipper-tumble.xml, ../examples/configs/flipper.xml",
        "hello-snake.xml, snake", "wheel.xml, wheel", "centipede-walk.xml, centipede",
        "gait-table-12.xml, snake", "standup-walk.xml, centipede", "teleop-dirwave.xml, snake:axes=alternate",
        "param-loop.xml, loop", "sensor-exit.xml, snake", "humanoid-wave.xml, ../examples/configs/humanoid15.xml"})
    void tenSimulatedMinutesStaySane(String file, String spec) {
        Program p = program(file);
        try (Simulator s = simulator(spec, p)) {
            assertEquals(RunOutcome.Status.COMPLETED, SimRun.run(p, s, 600, 0.01, d -> { }).status());
            assertFalse(s.hasNaN(), file + " produced NaN");
            for (SimBody b : s.snapshot().bodies()) {
                assertTrue(b.position().isFinite(), file + ": " + b);
                assertTrue(Math.abs(b.position().x()) < 100 && Math.abs(b.position().y()) < 100
                        && b.position().z() > -0.05 && b.position().z() < 5, file + ": " + b.part() + " left the box at "
                        + b.position());
            }
        }
    }
}
