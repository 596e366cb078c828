package org.parpe.cli.bench;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import org.parpe.core.diagram.Diagrams;
import org.parpe.core.diagram.Gait;
import org.parpe.core.diagram.Layouts;
import org.parpe.core.diagram.Scene;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Program;
import org.parpe.core.run.Breakpoints;
import org.parpe.core.run.Engine;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.WallClockPacer;

/**
 * {@code parpe bench --only diagram}: the time from a loaded program to the SVG text of each view
 * ({@code parpe diagram} without writing the file), on the 10 000-module script of the loading
 * benchmark (100 groups of 100 modules, one instance each). Goal: 200 ms per view (issue 24).
 * The gait view runs the engine for one period (2 s, 201 ticks of all 10 000 modules).
 *
 * <p>Then what the IDE's live views add to the engine thread, on {@code centipede-walk.xml}: the
 * breakpoint watcher ({@link Breakpoints}, which reads every module's state and exit after each
 * tick) in ns per tick of an unpaced run, and the lateness of the ticks of a real-time run
 * (wall clock at the tick's end less its due time) with and without it. The overlay's drawing
 * happens on the UI thread, which the engine never waits for.
 */
public final class DiagramBenchmark implements Benchmark {
    @Override
    public String name() {
        return "diagram";
    }

    @Override
    public List<Goal> goals() {
        return List.of(Goal.atMost("diagram.*_ms_median", 200));
    }

    @Override
    public void run(PrintStream out) throws Exception {
        LoadResult r = ScriptLoader.loadText(Path.of("bench-10000.xml"), CoreBenchmark.big(100, 100), Map.of());
        Program p = r.program();
        if (p == null) {
            throw new IllegalStateException("benchmark script does not load: " + r.diagnostics());
        }
        Behavior b = p.behaviors().get(0);
        Instance first = b.instances().get(0);
        Map<String, Supplier<Scene>> views = new java.util.LinkedHashMap<>();
        views.put("program", () -> Layouts.program(Diagrams.program(p).orElseThrow()));
        views.put("lanes", () -> Layouts.lanes(Diagrams.swimlanes(p, b)));
        views.put("ring", () -> Layouts.ring(Diagrams.ring(p, p.automata().get(0))));
        views.put("phase", () -> Layouts.wheel(Diagrams.wheel(first, first.on())));
        views.put("gait", () -> Layouts.gait(Gait.record(p, new RunOptions(0.01, 0, List.of()), 2)));
        out.printf(Locale.ROOT, "diagram.modules=%d%n", p.moduleIds().length);
        for (var v : views.entrySet()) {
            double[] ms = new double[v.getKey().equals("gait") ? 5 : 15];
            int bytes = 0;
            for (int i = 0; i < 3; i++) {
                bytes = v.getValue().get().svg().length();
            }
            for (int i = 0; i < ms.length; i++) {
                long t0 = System.nanoTime();
                bytes = v.getValue().get().svg().length();
                ms[i] = (System.nanoTime() - t0) / 1e6;
            }
            Arrays.sort(ms);
            out.printf(Locale.ROOT, "diagram.%s_ms_median=%.1f%n", v.getKey(), ms[ms.length / 2]);
            out.printf(Locale.ROOT, "diagram.%s_svg_bytes=%d%n", v.getKey(), bytes);
        }
        live(out);
    }

    private static void live(PrintStream out) throws Exception {
        Path file = Benchmark.examples().resolve("centipede-walk.xml");
        Program p = ScriptLoader.load(file, Map.of()).program();
        if (p == null) {
            throw new IllegalStateException("cannot load " + file);
        }
        // ns per tick, unpaced, without and with the watcher (best of five runs of 20 000 ticks)
        double[] perTick = new double[2];
        for (int with = 0; with < 2; with++) {
            double best = Double.POSITIVE_INFINITY;
            for (int rep = 0; rep < 6; rep++) {
                Engine e = new Engine(p, RunOptions.defaults());
                if (with == 1) {
                    e.addObserver(new Breakpoints().watch(e, () -> { }));
                }
                e.start();
                long t0 = System.nanoTime();
                for (int i = 0; i < 20_000; i++) {
                    e.step();
                }
                double ns = (System.nanoTime() - t0) / 20_000.0;
                best = rep == 0 ? best : Math.min(best, ns);
            }
            perTick[with] = best;
        }
        out.printf(Locale.ROOT, "diagram.live_engine_ns_per_tick=%.0f%n", perTick[0]);
        out.printf(Locale.ROOT, "diagram.live_watched_ns_per_tick=%.0f%n", perTick[1]);
        for (int with = 0; with < 2; with++) {
            double[] late = lateness(p, with == 1, 5);
            String k = with == 1 ? "watched" : "plain";
            out.printf(Locale.ROOT, "diagram.live_realtime_%s_late_ms_p50=%.3f%n", k, late[late.length / 2]);
            out.printf(Locale.ROOT, "diagram.live_realtime_%s_late_ms_p99=%.3f%n", k, late[late.length * 99 / 100]);
            out.printf(Locale.ROOT, "diagram.live_realtime_%s_late_ms_max=%.3f%n", k, late[late.length - 1]);
        }
    }

    /** Each tick's lateness (ms, sorted) in a real-time run of {@code seconds}, with or without the watcher. */
    private static double[] lateness(Program p, boolean watched, double seconds) {
        Run.Builder b = Run.builder(p, RunOptions.defaults(), d -> { });
        Engine e = b.engine();
        int ticks = (int) Math.round(seconds / e.dt()) + 1;
        long[] at = new long[ticks];
        b.pacer(new WallClockPacer(1));
        b.duration(seconds);
        if (watched) {
            b.observer(new Breakpoints().watch(e, () -> { }));
        }
        b.observer((tick, time, commanded) -> {
            if (tick < ticks) {
                at[(int) tick] = System.nanoTime();
            }
        });
        b.build().execute();
        double[] late = new double[ticks - 1];
        for (int k = 1; k < ticks; k++) {
            // tick 0 starts the clock; tick k is due k·dt later
            late[k - 1] = Math.max(0, (at[k] - at[0]) / 1e6 - k * e.dt() * 1000);
        }
        Arrays.sort(late);
        return late;
    }
}
