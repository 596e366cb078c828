package org.parpe.cli.bench;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.Map;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;

/**
 * Core figures: scheduler module updates per second for a 1 000-module snake whose angles are
 * expressions (goal ≥ 30 M/s on one core, issue 36), bytes allocated per tick (goal 0), and load +
 * validate time of a generated 10 000-module script (goal ≤ 200 ms). The scheduler's rate is per
 * second of the thread's CPU time (median of five rounds; {@code _wall} per wall-clock second).
 */
public final class CoreBenchmark implements Benchmark {
    @Override
    public String name() {
        return "core";
    }

    @Override
    public java.util.List<Goal> goals() {
        return java.util.List.of(Goal.atLeast("scheduler.module_updates_per_s", 30e6),
                Goal.atMost("scheduler.bytes_allocated_per_tick", 0), Goal.atMost("load.validate_ms_median", 200));
    }

    @Override
    public void run(PrintStream out) {
        scheduler(out);
        loading(out);
    }

    /** A snake of {@code n} modules driven by an expression wave. */
    public static String snake(int n) {
        return "<program><robot><structure><body elements=\"0.." + (n - 1) + "\"/></structure></robot>"
                + "<parameters><amp value=\"30\"/></parameters>"
                + "<controls><speed type=\"slider\" min=\"0.1\" max=\"5\" value=\"1\"/></controls>"
                + "<main><go/></main><behaviors><go><wave group=\"body\" phase=\"1/$count\" period=\"2/$speed\"/></go></behaviors>"
                + "<automata><wave states=\"crest, trough\"/></automata>"
                + "<states><crest angles=\"amp*sin(2*pi*$phase) + 2*cos(pi*$index/$count)\"/>"
                + "<trough angles=\"-amp*sin(2*pi*$phase + 0.5) - 5*$cycle/($cycle+1)\"/></states></program>";
    }

    private static void scheduler(PrintStream out) {
        int n = 1000;
        Program p = load(snake(n), "bench-snake.xml");
        Engine e = new Engine(p, RunOptions.defaults());
        e.start();
        for (int i = 0; i < 3000; i++) {
            e.step();
        }
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        double[] rates = new double[5];
        double[] wallRates = new double[rates.length];
        // the fewest bytes per tick of a round: a tick that allocates does so in every round, while a
        // one-off allocation of the JVM on this thread (a deoptimisation after late compilation) hits one
        double bytesPerTick = Double.POSITIVE_INFINITY;
        for (int round = 0; round < rates.length; round++) {
            // the thread's CPU time, as the simulator benchmark: on a shared machine the wall clock
            // also counts the time other processes had the core
            long allocBefore = mx.getThreadAllocatedBytes(Thread.currentThread().getId());
            long cpu = mx.getCurrentThreadCpuTime();
            long wall = System.nanoTime();
            long count = 0;
            while (mx.getCurrentThreadCpuTime() - cpu < 600_000_000L) {
                for (int i = 0; i < 100; i++) {
                    e.step();
                }
                count += 100;
            }
            rates[round] = count * (double) n / ((mx.getCurrentThreadCpuTime() - cpu) / 1e9);
            wallRates[round] = count * (double) n / ((System.nanoTime() - wall) / 1e9);
            long alloc = mx.getThreadAllocatedBytes(Thread.currentThread().getId()) - allocBefore;
            bytesPerTick = Math.min(bytesPerTick, alloc / (double) count);
        }
        Arrays.sort(rates);
        Arrays.sort(wallRates);
        out.printf(Locale.ROOT, "scheduler.modules=%d%n", n);
        out.printf(Locale.ROOT, "scheduler.module_updates_per_s=%.0f%n", rates[rates.length / 2]);
        out.printf(Locale.ROOT, "scheduler.module_updates_per_s_min=%.0f%n", rates[0]);
        out.printf(Locale.ROOT, "scheduler.module_updates_per_s_wall=%.0f%n", wallRates[wallRates.length / 2]);
        out.printf(Locale.ROOT, "scheduler.bytes_allocated_per_tick=%.2f%n", bytesPerTick);
    }

    /** A script with {@code groups} groups of {@code size} modules, sensors, states and one instance per group. */
    static String big(int groups, int size) {
        StringBuilder s = new StringBuilder("<program><robot><structure>\n");
        for (int g = 0; g < groups; g++) {
            s.append("<g").append(g).append(" elements=\"");
            for (int k = 0; k < size; k++) {
                s.append(k == 0 ? "" : ", ").append(g * size + k);
            }
            s.append("\"/>\n");
        }
        s.append("</structure><sensors><angle elements=\"all\"/><touch elements=\"g0, g1\"/></sensors></robot>\n");
        s.append("<parameters><amp value=\"20\" min=\"0\" max=\"90\"/></parameters>\n<states>\n");
        s.append("<up angles=\"amp*sin(2*pi*$phase)\"/><down angles=\"-amp + $_self_angle/10\"/></states>\n");
        s.append("<automata><wave states=\"up, down\" times=\"1, 1[$_self_angle &gt; 80]\"/></automata>\n<behaviors><all_waves>\n");
        for (int g = 0; g < groups; g++) {
            s.append("<wave group=\"g").append(g).append("\" phase=\"0.1\" offset=\"").append(g % 7 / 7.0).append("\" period=\"2\"/>\n");
        }
        s.append("</all_waves></behaviors><main><all_waves time=\"10\"/></main></program>\n");
        return s.toString();
    }

    private static void loading(PrintStream out) {
        String text = big(100, 100);
        double[] ms = new double[15];
        for (int i = 0; i < 10; i++) {
            load(text, "bench-10000.xml");
        }
        for (int i = 0; i < ms.length; i++) {
            long t0 = System.nanoTime();
            Program p = load(text, "bench-10000.xml");
            ms[i] = (System.nanoTime() - t0) / 1e6;
            if (p.moduleIds().length != 10_000) {
                throw new IllegalStateException("generated script has " + p.moduleIds().length + " modules");
            }
        }
        Arrays.sort(ms);
        out.printf(Locale.ROOT, "load.modules=10000%n");
        out.printf(Locale.ROOT, "load.script_bytes=%d%n", text.length());
        out.printf(Locale.ROOT, "load.validate_ms_median=%.1f%n", ms[ms.length / 2]);
        out.printf(Locale.ROOT, "load.validate_ms_min=%.1f%n", ms[0]);
    }

    private static Program load(String text, String name) {
        LoadResult r = ScriptLoader.loadText(Path.of(name), text, Map.of());
        if (r.program() == null) {
            throw new IllegalStateException("benchmark script does not load: " + r.diagnostics());
        }
        return r.program();
    }
}
