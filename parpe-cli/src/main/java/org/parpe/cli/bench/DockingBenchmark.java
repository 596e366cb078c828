package org.parpe.cli.bench;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.sim.SimTarget;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RootPose;
import org.parpe.sim.internal.Assembly;
import org.parpe.sim.internal.Docking;
import org.parpe.sim.internal.PhysicsParams;
import org.parpe.sim.internal.PhysicsWorld;

/**
 * Docking figures (PARSL.md §14, docs/simulator.md "Docking"): the real-time factor of the
 * snake → loop → snake example (examples/docking-snake-loop.xml on a ten-module snake, 25 s:
 * curl, latch, roll, release), and the cost of one docking check with every plate armed, for
 * robots of 8 to 512 loose modules (16 to 1 024 plates) laid in a line and in a square grid.
 * The check keeps the plates sorted by x and looks only at plates within reach along x, so its
 * cost per plate stays flat as the plates grow where checking every pair would grow with their
 * number. Times are the measuring thread's CPU time; each figure is the median of five rounds
 * after a warm-up.
 */
public final class DockingBenchmark implements Benchmark {
    private static final int ROUNDS = 5;
    private static final double LOOP_SECONDS = 25;
    /** Spacing of the loose modules, m: no plate within another's reach, as for most of a run. */
    private static final double SPACING = 0.2;

    private static final com.sun.management.ThreadMXBean MX =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    @Override
    public String name() {
        return "docking";
    }

    @Override
    public void run(PrintStream out) throws Exception {
        snakeLoop(out);
        for (int n : new int[] {8, 64, 512}) {
            search(out, "line", n, false);
            search(out, "grid", n, true);
        }
    }

    /** The snake → loop → snake example: simulated seconds per CPU second. */
    private static void snakeLoop(PrintStream out) throws Exception {
        LoadResult r = ScriptLoader.load(Benchmark.examples().resolve("docking-snake-loop.xml"), Map.of());
        if (r.program() == null) {
            throw new IllegalStateException("the docking example does not load: " + r.diagnostics());
        }
        double[] factor = new double[ROUNDS];
        for (int round = -1; round < ROUNDS; round++) {
            Run.Builder b = Run.builder(r.program(), new RunOptions(0.01, 0, List.of()), new DiagnosticList());
            SimTarget target = new SimTarget("snake:n=10");
            b.attach(target);
            Run run = b.duration(LOOP_SECONDS).build();
            long cpu0 = MX.getCurrentThreadCpuTime();
            run.execute();
            double cpu = (MX.getCurrentThreadCpuTime() - cpu0) / 1e9;
            if (round >= 0) {
                factor[round] = target.simulator().time() / cpu;
            }
        }
        Arrays.sort(factor);
        out.printf(Locale.ROOT, "docking.snake_loop.simulated_s=%.0f%n", LOOP_SECONDS);
        out.printf(Locale.ROOT, "docking.snake_loop.realtime_factor=%.1f%n", factor[ROUNDS / 2]);
        out.printf(Locale.ROOT, "docking.snake_loop.realtime_factor_min=%.1f%n", factor[0]);
    }

    /** One docking check with every plate of {@code n} loose modules armed: ns per check and per plate. */
    private static void search(PrintStream out, String layout, int n, boolean grid) {
        Assembly a = Assembly.build(loose(n, grid), new DiagnosticList());
        try (PhysicsWorld world = new PhysicsWorld(a, PhysicsParams.defaults())) {
            Docking docking = world.docking();
            int plates = a.plates().size();
            for (int s = 0; s < plates; s++) {
                docking.arm(s);
            }
            int calls = Math.max(200, 400_000 / plates);
            for (int i = 0; i < 5 * calls; i++) {
                docking.update(true);
            }
            double[] ns = new double[ROUNDS];
            long alloc0 = MX.getThreadAllocatedBytes(Thread.currentThread().getId());
            for (int round = 0; round < ROUNDS; round++) {
                long cpu0 = MX.getCurrentThreadCpuTime();
                for (int i = 0; i < calls; i++) {
                    docking.update(true);
                }
                ns[round] = (MX.getCurrentThreadCpuTime() - cpu0) / (double) calls;
            }
            long alloc = MX.getThreadAllocatedBytes(Thread.currentThread().getId()) - alloc0;
            Arrays.sort(ns);
            String key = "docking.search." + layout + n;
            out.printf(Locale.ROOT, "%s.armed_plates=%d%n", key, plates);
            out.printf(Locale.ROOT, "%s.ns_per_check=%.0f%n", key, ns[ROUNDS / 2]);
            out.printf(Locale.ROOT, "%s.ns_per_armed_plate=%.1f%n", key, ns[ROUNDS / 2] / plates);
            out.printf(Locale.ROOT, "%s.bytes_per_check=%.1f%n", key, alloc / (double) (ROUNDS * calls));
        }
    }

    /** {@code n} single segments, each a robot of its own root, in a line along x or a square grid. */
    private static RobotConfig loose(int n, boolean grid) {
        List<PartSpec> parts = new ArrayList<>();
        List<RootPose> roots = new ArrayList<>();
        int side = grid ? (int) Math.ceil(Math.sqrt(n)) : n;
        for (int i = 0; i < n; i++) {
            parts.add(PartSpec.segment("s" + i, i, 0));
            roots.add(new RootPose("s" + i, SPACING * (i % side), SPACING * (i / side), 90, 0, 0));
        }
        return new RobotConfig("loose" + n, parts, List.of(), roots);
    }
}
