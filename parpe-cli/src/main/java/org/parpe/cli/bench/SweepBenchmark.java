package org.parpe.cli.bench;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.parpe.core.model.Parameter;
import org.parpe.sim.sweep.Axis;
import org.parpe.sim.sweep.Cancellation;
import org.parpe.sim.sweep.Constraints;
import org.parpe.sim.sweep.Evaluator;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.OptimizationResult;
import org.parpe.sim.sweep.OptimizeSpec;
import org.parpe.sim.sweep.Optimizer;
import org.parpe.sim.sweep.Sweep;
import org.parpe.sim.sweep.SweepException;
import org.parpe.sim.sweep.SweepListener;
import org.parpe.sim.sweep.SweepResult;
import org.parpe.sim.sweep.SweepSpec;

/**
 * Sweep figures: simulations per second (wall clock) of the 8-module snake and the 55-module
 * centipede with one job and with every core, and the best forward speed that {@code optimize}
 * finds on the snake with a budget of 300 runs against the best of a 300-point random sweep
 * over the same bounds (lesson 10's race snake, 6 s per run). Throughput is that of a long sweep:
 * measured after warm-up passes until the JIT has finished (each worker's classes are compiled
 * on their own), as the median of eleven interleaved rounds, in a JVM with the collector
 * {@code parpe sweep} runs with. The machine's load
 * average is printed too: with other processes on the cores, the wall-clock speed-up of more
 * jobs shrinks while the CPU time per simulation ({@code cpu_s_per_sim}, or its inverse
 * {@code sims_per_cpu_s}) shows the overhead; {@code efficiency} is the speed-up divided by the
 * number of cores (1: every core adds a whole job's worth).
 */
public final class SweepBenchmark implements Benchmark {
    private static final int BUDGET = 300;
    private static final double RACE_SECONDS = 6;
    private static final int MIN_WARM_UP_PASSES = 3;
    private static final int MAX_WARM_UP_PASSES = 30;
    private static final int QUIET_PASSES = 3;
    private static final int ROUNDS = 11;

    /** Lesson 10's race snake: a travelling wave with bend, period and phase to tune. */
    static final String SNAKE = "<program><robot><structure><body elements=\"0..7\"/></structure></robot>"
            + "<parameters><bend value=\"30\" min=\"0\" max=\"80\"/><period value=\"2\" min=\"0.3\" max=\"5\"/>"
            + "<phase value=\"0.2\" min=\"0\" max=\"1\"/></parameters><main><race/></main>"
            + "<behaviors><race><wave group=\"body\" phase=\"phase\" period=\"period\"/></race></behaviors>"
            + "<automata><wave states=\"up, down\"/></automata>"
            + "<states><up angles=\"bend\" interp=\"smooth\"/><down angles=\"-bend\" interp=\"smooth\"/></states></program>";

    /** The paper's centipede walk with its period as a parameter, on the {@code centipede} generator's IDs. */
    static final String CENTIPEDE = "<program><robot><structure><leftSwing elements=\"0,2,4,6,8,10,12\"/>"
            + "<leftLift elements=\"1,3,5,7,9,11,13\"/><rightSwing elements=\"14,16,18,20,22,24,26\"/>"
            + "<rightLift elements=\"15,17,19,21,23,25,27\"/><spine elements=\"28..54\"/></structure></robot>"
            + "<parameters><period value=\"3\" min=\"2\" max=\"4\"/></parameters>"
            + "<main><walk/></main><behaviors><walk>"
            + "<swing group=\"!leftSwing\" offset=\"0\" phase=\"0.75\" period=\"period\"/>"
            + "<swing group=\"rightSwing\" offset=\"0.5\" phase=\"0.75\" period=\"period\"/>"
            + "<step group=\"leftLift\" offset=\"0\" phase=\"0.75\" period=\"period\"/>"
            + "<step group=\"rightLift\" offset=\"0.5\" phase=\"0.75\" period=\"period\"/></walk></behaviors>"
            + "<automata><swing states=\"reach, push\" times=\"1, 2\"/>"
            + "<step states=\"raise, lower, stance\" times=\"0.5, 0.5, 2\"/></automata>"
            + "<states><reach angles=\"25\"/><push angles=\"-25\"/><raise angles=\"20\"/>"
            + "<lower angles=\"-60\"/><stance angles=\"-60\"/></states></program>";

    private static final java.lang.management.CompilationMXBean JIT =
            java.lang.management.ManagementFactory.getCompilationMXBean();
    private static final com.sun.management.OperatingSystemMXBean OS =
            (com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory.getOperatingSystemMXBean();

    @Override
    public String name() {
        return "sweep";
    }

    /** Issue 36: with every core, at least 0.9 × the number of cores the speed of one job. */
    @Override
    public List<Goal> goals() {
        return List.of(Goal.atLeast("sweep.*.speedup", 0.9 * Runtime.getRuntime().availableProcessors()));
    }

    /** The collector {@code parpe sweep} and {@code parpe optimize} run with (the launcher's default). */
    @Override
    public List<String> jvmOptions() {
        return List.of("-XX:+UseParallelGC");
    }

    @Override
    public void run(PrintStream out) throws SweepException {
        int cores = Runtime.getRuntime().availableProcessors();
        out.printf(Locale.ROOT, "sweep.cores=%d%n", cores);
        out.printf(Locale.ROOT, "sweep.load_average_before=%.2f%n", OS.getSystemLoadAverage());
        throughput(out, "snake8", evaluator("bench-snake.xml", SNAKE, "snake:n=8", 5), "bend", 60, cores);
        throughput(out, "centipede55", evaluator("bench-centipede.xml", CENTIPEDE, "centipede", 3), "period", 16, cores);
        optimiseVersusRandom(out, cores);
    }

    private static Evaluator evaluator(String name, String text, String robot, double seconds) throws SweepException {
        return Evaluator.load(new Evaluator.Settings(Path.of(name), text, Map.of(), robot, seconds, 0.01, 90));
    }

    /**
     * Simulations per second for {@code runs} runs with one job and with every core, in the
     * steady state of a long sweep: after warm-up passes until the JIT is done, the median of
     * interleaved rounds.
     */
    private static void throughput(PrintStream out, String label, Evaluator ev, String param, int runs, int cores)
            throws SweepException {
        Parameter p = ev.parameters().stream().filter(q -> q.name().equals(param)).findFirst().orElseThrow();
        Axis axis = Axis.even(param, p.min(), p.max(), runs);
        Sweep sweep = new Sweep(ev, SweepSpec.grid(List.of(axis), 1, 0));
        // Each worker simulates in its own copy of the physics classes, compiled by the JIT on its
        // own, and each run loads its script and builds its physics world afresh: code that runs
        // once per run and so reaches its compiled form only after hundreds of runs. Until then
        // the compiler threads take CPU time, which is free for one job (the spare core) but comes
        // out of the simulations when every core is busy. So: whole passes of both until three
        // passes in a row spend under 2 % of their time compiling (a long sweep's steady state).
        int passes = 0;
        int quiet = 0;
        while (passes < MAX_WARM_UP_PASSES && (passes < MIN_WARM_UP_PASSES || quiet < QUIET_PASSES)) {
            long jit0 = JIT.getTotalCompilationTime();
            long t0 = System.nanoTime();
            sweep.run(cores, SweepListener.NONE, new Cancellation());
            sweep.run(1, SweepListener.NONE, new Cancellation());
            double compiling = (JIT.getTotalCompilationTime() - jit0) / ((System.nanoTime() - t0) / 1e6);
            quiet = compiling < 0.02 ? quiet + 1 : 0;
            passes++;
        }
        // Rounds of one job then every core, interleaved so that a drift of the machine's speed
        // touches both; the medians are printed (on a virtual machine single rounds scatter by
        // a tenth and more, with the host's other guests).
        double[][] ones = new double[ROUNDS][];
        double[][] alls = new double[ROUNDS][];
        long jit0 = JIT.getTotalCompilationTime();
        long t0 = System.nanoTime();
        for (int round = 0; round < ROUNDS; round++) {
            ones[round] = rate(sweep, 1);
            alls[round] = rate(sweep, cores);
        }
        double jitShare = (JIT.getTotalCompilationTime() - jit0) / ((System.nanoTime() - t0) / 1e6);
        double[] one = median(ones);
        double[] all = median(alls);
        // The speed-up of each round (one job, then every core, a few seconds apart) and their
        // median: pairing cancels a drift of the machine's speed between rounds.
        double[][] ratios = new double[ROUNDS][1];
        StringBuilder each = new StringBuilder();
        for (int round = 0; round < ROUNDS; round++) {
            ratios[round][0] = alls[round][0] / ones[round][0];
            each.append(round == 0 ? "" : ",").append(String.format(Locale.ROOT, "%.2f", ratios[round][0]));
        }
        out.printf(Locale.ROOT, "sweep.%s.warm_up_passes=%d%n", label, passes);
        out.printf(Locale.ROOT, "sweep.%s.sims_per_s.jobs1=%.2f%n", label, one[0]);
        out.printf(Locale.ROOT, "sweep.%s.sims_per_s.jobs%d=%.2f%n", label, cores, all[0]);
        out.printf(Locale.ROOT, "sweep.%s.speedup=%.2f%n", label, median(ratios)[0]);
        out.printf(Locale.ROOT, "sweep.%s.speedup_of_medians=%.2f%n", label, all[0] / one[0]);
        out.printf(Locale.ROOT, "sweep.%s.speedup_per_round=%s%n", label, each);
        // Runs per CPU-second (every thread of this process, the JIT and the collector too): the
        // cost of a run whatever else the machine is doing; and the speed-up's efficiency, the
        // share of the ideal (one more core, one more job's worth) that every core gave.
        out.printf(Locale.ROOT, "sweep.%s.sims_per_cpu_s.jobs1=%.2f%n", label, 1 / one[1]);
        out.printf(Locale.ROOT, "sweep.%s.sims_per_cpu_s.jobs%d=%.2f%n", label, cores, 1 / all[1]);
        out.printf(Locale.ROOT, "sweep.%s.efficiency=%.2f%n", label, median(ratios)[0] / cores);
        out.printf(Locale.ROOT, "sweep.%s.cpu_s_per_sim.jobs1=%.3f%n", label, one[1]);
        out.printf(Locale.ROOT, "sweep.%s.cpu_s_per_sim.jobs%d=%.3f%n", label, cores, all[1]);
        out.printf(Locale.ROOT, "sweep.%s.jit_share_while_measuring=%.3f%n", label, jitShare);
    }

    /** The median of each column. */
    private static double[] median(double[][] rows) {
        double[] m = new double[rows[0].length];
        for (int c = 0; c < m.length; c++) {
            double[] col = new double[rows.length];
            for (int r = 0; r < rows.length; r++) {
                col[r] = rows[r][c];
            }
            java.util.Arrays.sort(col);
            m[c] = col[col.length / 2];
        }
        return m;
    }

    /** Simulations per wall-clock second and CPU seconds (all threads of this process) per simulation. */
    private static double[] rate(Sweep sweep, int jobs) {
        long cpu0 = OS.getProcessCpuTime();
        long t0 = System.nanoTime();
        SweepResult r = sweep.run(jobs, SweepListener.NONE, new Cancellation());
        double wall = (System.nanoTime() - t0) / 1e9;
        double cpu = (OS.getProcessCpuTime() - cpu0) / 1e9;
        return new double[] {r.rows().size() / wall, cpu / r.rows().size()};
    }

    private static void optimiseVersusRandom(PrintStream out, int cores) throws SweepException {
        Evaluator ev = evaluator("bench-race-snake.xml", SNAKE, "snake:n=8", RACE_SECONDS);
        long t0 = System.nanoTime();
        OptimizationResult opt = new Optimizer(ev, new OptimizeSpec(Objective.FORWARD_SPEED, Constraints.NONE, BUDGET,
                4, 1)).run(cores, SweepListener.NONE, new Cancellation());
        double optSeconds = (System.nanoTime() - t0) / 1e9;
        t0 = System.nanoTime();
        SweepResult random = new Sweep(ev, SweepSpec.random(SweepSpec.declaredSpace(ev.parameters(), Set.of()), BUDGET,
                1, 1)).run(cores, SweepListener.NONE, new Cancellation());
        double randomSeconds = (System.nanoTime() - t0) / 1e9;
        double defaults = opt.starts().get(0).get(0).score();
        out.printf(Locale.ROOT, "sweep.race_snake.defaults_forward_speed_mps=%.4f%n", defaults);
        out.printf(Locale.ROOT, "sweep.race_snake.optimize%d.best_forward_speed_mps=%.4f%n", BUDGET,
                opt.best().orElseThrow().score());
        out.printf(Locale.ROOT, "sweep.race_snake.random%d.best_forward_speed_mps=%.4f%n", BUDGET,
                random.best(Objective.FORWARD_SPEED).map(Objective.FORWARD_SPEED::of).orElse(Double.NaN));
        out.printf(Locale.ROOT, "sweep.race_snake.optimize%d.seconds=%.1f%n", BUDGET, optSeconds);
        out.printf(Locale.ROOT, "sweep.race_snake.random%d.seconds=%.1f%n", BUDGET, randomSeconds);
        opt.best().ifPresent(b -> out.printf(Locale.ROOT, "sweep.race_snake.optimize%d.best_values=%s%n", BUDGET,
                b.row().values()));
    }
}
