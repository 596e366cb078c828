package org.parpe.cli.sim;

import java.io.PrintStream;
import java.nio.file.Path;
import java.lang.management.ManagementFactory;
import java.util.List;
import java.util.Locale;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.cli.bench.Benchmark;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.model.Program;
import org.parpe.sim.Simulator;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;
import org.parpe.sim.config.RobotConfigs;

/**
 * Simulator figures: real-time factor (simulated seconds per wall-clock second, one thread) of
 * an 8-module snake, the paper's 55-module centipede walking (goal ≥ 25) and a 200-module
 * snake, the centipede in the rubble world (goal ≥ 15) and the 8-module snake in the race world
 * (goal ≥ 100), plus bytes allocated per tick. Each case warms up, then runs for 3 s of its thread's CPU
 * time; {@code realtime_factor} divides simulated time by that CPU time (one core, unaffected by
 * other processes), {@code realtime_factor_wall} by the elapsed wall-clock time.
 */
public final class SimBenchmark implements Benchmark {
    private static final double DT = 0.01;
    private static final long MEASURE_NANOS = 2_000_000_000L;
    private static final int ROUNDS = 3;

    @Override
    public String name() {
        return "sim";
    }

    /** Issue 36's goals: real-time factors on one core, at most 1 KB allocated per tick. */
    @Override
    public List<org.parpe.cli.bench.Goal> goals() {
        return List.of(org.parpe.cli.bench.Goal.atLeast("sim.snake8.realtime_factor", 400),
                org.parpe.cli.bench.Goal.atLeast("sim.centipede55.realtime_factor", 60),
                org.parpe.cli.bench.Goal.atLeast("sim.snake200.realtime_factor", 20),
                org.parpe.cli.bench.Goal.atLeast("sim.centipede55_rubble.realtime_factor", 45),
                org.parpe.cli.bench.Goal.atLeast("sim.snake8_race_track.realtime_factor", 100),
                org.parpe.cli.bench.Goal.atMost("sim.*.bytes_per_tick", 1024));
    }

    @Override
    public void run(PrintStream out) throws Exception {
        measure(out, "snake8", "snake:n=8", snakeScript(8), null);
        measure(out, "centipede55", "centipede", centipedeScript(), null);
        measure(out, "snake200", "snake:n=200", snakeScript(200), null);
        measure(out, "centipede55_rubble", "centipede", centipedeScript(), world("rubble.xml"));
        measure(out, "snake8_race_track", "snake:n=8", snakeScript(8), world("race-track.xml"));
    }

    /** An example world of {@code examples/worlds}. */
    private static World world(String name) throws Exception {
        Path file = Benchmark.examples().resolve("worlds").resolve(name);
        DiagnosticList found = new DiagnosticList();
        World w = WorldReader.read(file, found);
        if (w == null) {
            throw new IllegalStateException("the benchmark world " + file + " does not load: " + found.all());
        }
        return w;
    }

    /** A travelling wave over every module of an {@code n}-module snake. */
    static String snakeScript(int n) {
        return "<program><robot><structure><body elements=\"0.." + (n - 1) + "\"/></structure></robot>"
                + "<main><go/></main><behaviors><go><wave group=\"body\" phase=\"0.125\" period=\"1\"/></go></behaviors>"
                + "<automata><wave states=\"up, down\"/></automata>"
                + "<states><up angles=\"30\"/><down angles=\"-30\"/></states></program>";
    }

    /** The paper's centipede walk, as in {@code examples/centipede-walk.xml}, on the {@code centipede} generator's IDs. */
    static String centipedeScript() {
        return "<program><robot><structure><leftSwing elements=\"0,2,4,6,8,10,12\"/>"
                + "<leftLift elements=\"1,3,5,7,9,11,13\"/><rightSwing elements=\"14,16,18,20,22,24,26\"/>"
                + "<rightLift elements=\"15,17,19,21,23,25,27\"/><spine elements=\"28..54\"/></structure></robot>"
                + "<main><walk/></main><behaviors><walk>"
                + "<swing group=\"!leftSwing\" offset=\"0\" phase=\"0.75\" period=\"3\"/>"
                + "<swing group=\"rightSwing\" offset=\"0.5\" phase=\"0.75\" period=\"3\"/>"
                + "<step group=\"leftLift\" offset=\"0\" phase=\"0.75\" period=\"3\"/>"
                + "<step group=\"rightLift\" offset=\"0.5\" phase=\"0.75\" period=\"3\"/></walk></behaviors>"
                + "<automata><swing states=\"reach, push\" times=\"1, 2\"/>"
                + "<step states=\"raise, lower, stance\" times=\"0.5, 0.5, 2\"/></automata>"
                + "<states><reach angles=\"25\"/><push angles=\"-25\"/><raise angles=\"20\"/>"
                + "<lower angles=\"-60\"/><stance angles=\"-60\"/></states></program>";
    }

    private static void measure(PrintStream out, String label, String spec, String script, World world) {
        Program program = SimRun.load("bench-" + label + ".xml", script);
        DiagnosticList diags = new DiagnosticList();
        try (Simulator sim = new Simulator(RobotConfigs.resolve(spec, program.moduleIds(), diags), world)) {
            Engine engine = new Engine(program, new RunOptions(DT, 0, List.of()));
            engine.addPlant(sim);
            engine.setSensorSource(sim);
            engine.start();
            // Warm up until the JIT has compiled ODE's solver, then take the median of three rounds.
            com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
            long warm0 = mx.getCurrentThreadCpuTime();
            while (mx.getCurrentThreadCpuTime() - warm0 < MEASURE_NANOS) {
                for (int i = 0; i < 50; i++) {
                    engine.step();
                }
            }
            double[] cpuFactor = new double[ROUNDS];
            double[] wallFactor = new double[ROUNDS];
            long alloc = 0;
            long ticks = 0;
            for (int round = 0; round < ROUNDS; round++) {
                long alloc0 = mx.getThreadAllocatedBytes(Thread.currentThread().getId());
                double t0 = sim.time();
                long start = System.nanoTime();
                long cpu0 = mx.getCurrentThreadCpuTime();
                while (mx.getCurrentThreadCpuTime() - cpu0 < MEASURE_NANOS) {
                    for (int i = 0; i < 50; i++) {
                        engine.step();
                    }
                    ticks += 50;
                }
                wallFactor[round] = (sim.time() - t0) / ((System.nanoTime() - start) / 1e9);
                cpuFactor[round] = (sim.time() - t0) / ((mx.getCurrentThreadCpuTime() - cpu0) / 1e9);
                alloc += mx.getThreadAllocatedBytes(Thread.currentThread().getId()) - alloc0;
            }
            java.util.Arrays.sort(cpuFactor);
            java.util.Arrays.sort(wallFactor);
            out.printf(Locale.ROOT, "sim.%s.modules=%d%n", label, sim.moduleIds().length);
            out.printf(Locale.ROOT, "sim.%s.bodies=%d%n", label, sim.snapshot().bodies().size());
            out.printf(Locale.ROOT, "sim.%s.realtime_factor=%.1f%n", label, cpuFactor[ROUNDS / 2]);
            out.printf(Locale.ROOT, "sim.%s.realtime_factor_min=%.1f%n", label, cpuFactor[0]);
            out.printf(Locale.ROOT, "sim.%s.realtime_factor_wall=%.1f%n", label, wallFactor[ROUNDS / 2]);
            out.printf(Locale.ROOT, "sim.%s.bytes_per_tick=%d%n", label, alloc / Math.max(1, ticks));
            out.printf(Locale.ROOT, "sim.%s.distance_m=%.3f%n", label, sim.metrics().distance());
        }
    }
}
