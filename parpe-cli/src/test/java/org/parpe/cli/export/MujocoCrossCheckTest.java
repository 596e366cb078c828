package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.cli.Cli;

/**
 * PARPE's simulator held against MuJoCo 3 (issue 34): each example gait runs 20 s in PARPE
 * ({@code parpe run --metrics}) and, from the same commanded angles, in MuJoCo
 * ({@code parpe export --target mjcf} and its runner's {@code --metrics}); the two must agree on
 * how far the centre of mass went (within 20 %), its heading (within 15°) and whether the
 * robot fell (tilt over 90°), both run at a 1 ms tick. The Fig. 7 wheel rolls in neither engine
 * at that tick (PARPE's roll at 2 and 5 ms is its solver's, not the model's), so it is held to
 * staying where it is in both. docs/simulator.md ("PARPE against MuJoCo") gives every figure
 * and why the others differ.
 */
class MujocoCrossCheckTest {
    enum Check {
        DISTANCE, HEADING, FELL,
        /**
         * Neither engine moves the robot as far as a wheel's spoke pitch ({@link #PITCH}): a gait
         * that goes nowhere in both, whose few centimetres of rocking are no distance to compare.
         */
        STAYS
    }

    /**
     * The arc from one foot of the 8-spoke wheel to the next, m: 2π × 0.16 m (the feet's outer
     * faces) / 8. A wheel that rolled onto its next foot and stayed there has gone this far.
     */
    static final double PITCH = 2 * Math.PI * 0.1604 / 8;

    record Gait(String script, String robot, Set<Check> checks) {
        @Override
        public String toString() {
            return Path.of(script).getFileName() + " on " + robot;
        }
    }

    static List<Gait> gaits() {
        Set<Check> moves = EnumSet.of(Check.DISTANCE, Check.HEADING, Check.FELL);
        return List.of(
                new Gait("../examples/hello-snake.xml", "snake:n=8", moves),
                new Gait("../examples/centipede-walk.xml", "centipede", moves),
                new Gait("../examples/tutorial/10-race-snake.xml", "snake:n=8", moves),
                new Gait("../examples/standup-walk.xml", "centipede", moves),
                new Gait("../examples/wheel.xml", "wheel", EnumSet.of(Check.STAYS, Check.FELL)));
    }

    /**
     * The tick of both runs, s: 1 ms, so that PARPE steps its physics in 1 ms. At its default 5 ms
     * sub-step (10 solver iterations) PARPE's figures are not converged: the snakes go a third less
     * far, standup-walk 0.10 m instead of 0.28 m, and the wheel rolls 1.6 m that it does not roll
     * at 1 ms or with more iterations; at 2 ms standup-walk still goes 0.245 m (MuJoCo 1.34 ×) and
     * the wheel 0.8 m (docs/simulator.md, "PARPE against MuJoCo").
     */
    static final String TICK = "0.001";

    @TempDir
    Path dir;

    /** Metrics of a run: distance (m), dx, dy, maxTiltDeg. */
    record Metrics(double distance, double dx, double dy, double maxTiltDeg) {
        double headingDeg() {
            return Math.toDegrees(Math.atan2(dy, dx));
        }

        boolean fell() {
            return maxTiltDeg > 90;
        }

        static Metrics of(String json) {
            return new Metrics(number(json, "distance"), number(json, "dx"), number(json, "dy"), number(json, "maxTiltDeg"));
        }

        private static double number(String json, String key) {
            Matcher m = Pattern.compile("\"" + key + "\": (-?[0-9.]+)").matcher(json);
            assertTrue(m.find(), key + " in " + json);
            return Double.parseDouble(m.group(1));
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("gaits")
    void mujocoAgreesWithParpe(Gait g) throws Exception {
        String py = BridgeTools.python();
        Metrics parpe = parpe(g.script(), g.robot());
        Metrics mujoco = mujoco(py, g.script(), g.robot());
        String figures = "PARPE " + parpe + ", MuJoCo " + mujoco;
        if (g.checks().contains(Check.DISTANCE)) {
            assertTrue(Math.abs(mujoco.distance() - parpe.distance()) <= 0.2 * parpe.distance(), "distance: " + figures);
        }
        if (g.checks().contains(Check.HEADING)) {
            double diff = Math.abs(Math.IEEEremainder(mujoco.headingDeg() - parpe.headingDeg(), 360));
            assertTrue(diff <= 15, "heading differs by " + diff + "°: " + figures);
        }
        if (g.checks().contains(Check.STAYS)) {
            assertTrue(parpe.distance() < PITCH && mujoco.distance() < PITCH, "stays within " + PITCH + " m: " + figures);
        }
        assertEquals(parpe.fell(), mujoco.fell(), "fell: " + figures);
    }

    /** Lesson 10's race: the optimised snake beats the lesson's in both engines. */
    @Test
    void bothEnginesRankTheRaceLessonsGaitsAlike() throws Exception {
        String py = BridgeTools.python();
        String lesson = "../examples/tutorial/10-race-snake.xml";
        String optimised = "../examples/race-snake-optimised.xml";
        Metrics parpeLesson = parpe(lesson, "snake:n=8");
        Metrics parpeOptimised = parpe(optimised, "snake:n=8");
        Metrics mujocoLesson = mujoco(py, lesson, "snake:n=8");
        Metrics mujocoOptimised = mujoco(py, optimised, "snake:n=8");
        assertTrue(parpeOptimised.distance() > parpeLesson.distance(), parpeOptimised + " vs " + parpeLesson);
        assertTrue(mujocoOptimised.distance() > mujocoLesson.distance(), mujocoOptimised + " vs " + mujocoLesson);
    }

    /**
     * The fastest example gait (0.3 s waves, past the servo's 300°/s), exported at PARPE's
     * default tick: MuJoCo stays stable (at a 1 ms step its servo made this snake diverge, 195 m
     * backwards on its back) and agrees with PARPE that it does not fall and where it heads.
     */
    @Test
    void theFastestGaitStaysStableAtTheDefaultTick() throws Exception {
        String py = BridgeTools.python();
        String optimised = "../examples/race-snake-optimised.xml";
        Metrics parpe = parpe(optimised, "snake:n=8", "0.01");
        Metrics mujoco = mujoco(py, optimised, "snake:n=8", "0.01");
        String figures = "PARPE " + parpe + ", MuJoCo " + mujoco;
        assertEquals(parpe.fell(), mujoco.fell(), figures);
        assertTrue(Math.abs(Math.IEEEremainder(mujoco.headingDeg() - parpe.headingDeg(), 360)) <= 15, figures);
        assertTrue(mujoco.distance() < parpe.distance(), figures);
    }

    /**
     * Friction as PARPE has it in every direction along the floor: ODE's friction pyramid
     * ({@code dContactApprox1}; ODE manual, "Concepts", "Friction approximation": up to mu times
     * the normal force along each of the two friction directions) holds a part against a pull of
     * 0.9 mu times its weight whatever the pull's direction, as Coulomb's cone does. MuJoCo's
     * default pyramid (MuJoCo documentation, "Computation", "Contact", pyramidal and elliptic
     * cones) has its edges at mu along the friction axes, so only mu/sqrt(2) between them, and at
     * 45° the export slid where PARPE holds (0.57 m in a second); with the elliptic cone it holds.
     */
    @Test
    void theExportHoldsAPullAcrossTheFloorAsParpeDoes() throws Exception {
        String py = BridgeTools.python();
        Path out = Files.createTempDirectory(dir, "mj");
        Cli r = Cli.run("export", "--target", "mjcf", "--robot", "snake:n=8", "--out", out.toString());
        assertEquals(0, r.code, r.toString());
        String pull = String.join("\n",
                "import math, sys, mujoco",
                "m = mujoco.MjModel.from_xml_path(sys.argv[1]); d = mujoco.MjData(m)",
                "f = 0.9 * 0.6 * 9.81 / math.sqrt(2)",
                "m.opt.gravity[:] = (f, f, -9.81)",
                "mujoco.mj_forward(m, d); start = d.subtree_com[0].copy()",
                "for _ in range(round(1 / m.opt.timestep)): mujoco.mj_step(m, d)",
                "print(math.hypot(*(d.subtree_com[0] - start)[:2]))");
        String model = out.resolve("snake_n_8.xml").toString();
        double slid = Double.parseDouble(BridgeTools.run(dir, List.of(py, "-c", pull, model)).trim());
        assertTrue(slid < 0.01, "slid " + slid + " m in 1 s under a pull of 0.9 mu g at 45°");
    }

    private Metrics parpe(String script, String robot) throws Exception {
        return parpe(script, robot, TICK);
    }

    private Metrics mujoco(String py, String script, String robot) throws Exception {
        return mujoco(py, script, robot, TICK);
    }

    private Metrics parpe(String script, String robot, String tick) throws Exception {
        Path json = Files.createTempFile(dir, "parpe", ".json");
        Cli r = Cli.run("run", script, "--sim", robot, "--duration", "20", "--tick", tick, "--metrics", json.toString());
        assertEquals(0, r.code, r.toString());
        return Metrics.of(Files.readString(json));
    }

    private Metrics mujoco(String py, String script, String robot, String tick) throws Exception {
        Path out = Files.createTempDirectory(dir, "mj");
        Cli r = Cli.run("export", "--target", "mjcf", "--robot", robot, "--out", out.toString(), "--duration", "20", "--tick", tick, script);
        assertEquals(0, r.code, r.toString());
        Path model;
        Path controls;
        try (var files = Files.list(out)) {
            List<Path> all = files.toList();
            controls = all.stream().filter(f -> f.toString().endsWith(".ctrl.csv")).findFirst().orElseThrow();
            model = all.stream().filter(f -> f.toString().endsWith(".xml")).findFirst().orElseThrow();
        }
        Path json = out.resolve("metrics.json");
        BridgeTools.run(dir, List.of(py, out.resolve("play_mujoco.py").toString(), model.toString(), controls.toString(),
                "--out", out.resolve("trace.csv").toString(), "--metrics", json.toString()));
        return Metrics.of(Files.readString(json));
    }
}
