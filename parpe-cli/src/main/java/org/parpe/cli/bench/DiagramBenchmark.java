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
import org.parpe.core.run.RunOptions;

/**
 * {@code parpe bench --only diagram}: the time from a loaded program to the SVG text of each view
 * ({@code parpe diagram} without writing the file), on the 10 000-module script of the loading
 * benchmark (100 groups of 100 modules, one instance each). Goal: 200 ms per view (issue 24).
 * The gait view runs the engine for one period (2 s, 201 ticks of all 10 000 modules).
 */
public final class DiagramBenchmark implements Benchmark {
    @Override
    public String name() {
        return "diagram";
    }

    @Override
    public void run(PrintStream out) {
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
        views.put("ring", () -> Layouts.ring(Diagrams.ring(p.automata().get(0))));
        views.put("phase", () -> Layouts.wheel(Diagrams.wheel(first, p.group(first.group()).orElseThrow())));
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
        out.printf(Locale.ROOT, "diagram.goal_ms=200%n");
    }
}
