package org.parpe.cli.sim;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.parpe.cli.ClockOptions;
import org.parpe.cli.Inputs;
import org.parpe.cli.UsageException;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.RunOutcome;
import org.parpe.sim.SimMetrics;
import org.parpe.sim.Simulator;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code parpe race}: runs several scripts on the same simulated robot and ranks them by distance. */
@Command(name = "race", mixinStandardHelpOptions = true, description = "Run scripts on the simulator, each on a fresh robot, and rank them by the"
        + " distance their robot's centre of mass travelled.")
public final class RaceCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "FILE", description = "PARSL scripts to race.")
    List<Path> files = new ArrayList<>();

    @Option(names = "--sim", paramLabel = "ROBOT", defaultValue = "snake",
            description = "GENERATOR[:key=value,...] or CONFIG.xml (default: a snake of each script's modules).")
    String sim;

    @Option(names = "--duration", paramLabel = "SECONDS", defaultValue = "20",
            description = "Simulated seconds per script (default ${DEFAULT-VALUE}).")
    double duration;

    @Option(names = "--tick", paramLabel = "SECONDS", defaultValue = "0.01", description = "Scheduler tick (default ${DEFAULT-VALUE}).")
    double tick;

    @Spec
    CommandSpec spec;

    private record Entry(String script, SimMetrics metrics, String problem) {
    }

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        List<Entry> entries = new ArrayList<>();
        try {
            if (!(duration > 0)) {
                throw new UsageException("--duration must be > 0 seconds, got " + duration);
            }
            ClockOptions.check(tick, duration);
            for (Path f : files) {
                Inputs.check(f);
            }
            for (Path f : files) {
                entries.add(race(f, err));
            }
        } catch (UsageException u) {
            err.println("parpe: " + u.getMessage());
            return 2;
        }
        entries.sort(Comparator.comparing((Entry e) -> e.metrics() == null)
                .thenComparing(e -> e.metrics() == null ? 0 : -e.metrics().distance()));
        print(out, entries);
        out.flush();
        return entries.stream().anyMatch(e -> e.metrics() == null) ? 1 : 0;
    }

    private Entry race(Path file, PrintWriter err) throws UsageException {
        LoadResult r = ScriptLoader.load(file, Map.of());
        for (Diagnostic d : r.diagnostics()) {
            err.println(d.format());
        }
        if (r.program() == null || r.program().main() == null) {
            return new Entry(file.toString(), null, r.program() == null ? "script errors" : "no <main>");
        }
        java.io.PrintStream errStream = new java.io.PrintStream(new java.io.OutputStream() {
            @Override
            public void write(int b) {
                err.write(b);
            }
        }, true, java.nio.charset.StandardCharsets.UTF_8);
        try (Simulator s = SimOptions.create(sim, r.program().moduleIds(), errStream)) {
            RunOutcome outcome = SimRun.run(r.program(), s, duration, tick, d -> err.println(d.format()));
            if (outcome.status() == RunOutcome.Status.ERROR) {
                return new Entry(file.toString(), null, "run-time error");
            }
            return new Entry(file.toString(), s.metrics(), "");
        }
    }

    private static void print(PrintWriter out, List<Entry> entries) {
        int width = Math.max(6, entries.stream().mapToInt(e -> e.script().length()).max().orElse(6));
        out.println(String.format(Locale.ROOT, "%-4s  %-" + width + "s  %12s  %11s  %13s", "rank", "script",
                "distance (m)", "speed (m/s)", "max tilt (°)"));
        int rank = 1;
        for (Entry e : entries) {
            if (e.metrics() == null) {
                out.println(String.format(Locale.ROOT, "%-4s  %-" + width + "s  %s", "-", e.script(), e.problem()));
            } else {
                out.println(String.format(Locale.ROOT, "%-4d  %-" + width + "s  %12.3f  %11.4f  %13.1f", rank++,
                        e.script(), e.metrics().distance(), e.metrics().speed(), e.metrics().maxTiltDeg()));
            }
        }
    }
}
