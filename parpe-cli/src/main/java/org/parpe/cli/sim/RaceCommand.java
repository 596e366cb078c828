package org.parpe.cli.sim;

import org.parpe.cli.text.CliMsg;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.parpe.cli.options.ClockOptions;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.UsageException;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.RunOutcome;
import org.parpe.sim.SimMetrics;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;
import org.parpe.sim.world.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code parpe race}: runs several scripts on the simulator, each on a fresh robot of its own
 * kind (or the one {@code --sim} names), and ranks them by how far the centre of mass went
 * forwards (+x, the way every standard robot faces), or in a world ({@code --world}) by score.
 */
@Command(name = "race", mixinStandardHelpOptions = true, description = "Run scripts on the simulator, each on a fresh"
        + " robot, and rank them by how far their robot's centre of mass went forwards (+x), or with --world by"
        + " the world's score.")
public final class RaceCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "FILE", descriptionKey = "files", description = "PARSL scripts to race.")
    List<Path> files = new ArrayList<>();

    @Option(names = "--sim", paramLabel = "ROBOT",
            description = "GENERATOR[:key=value,...] or CONFIG.xml for every script (default: each script's own"
                    + " robot, as the IDE's 'auto' picks it: a wheel script races as a wheel, a snake as a snake).")
    String sim;

    @Option(names = "--duration", paramLabel = "SECONDS",
            description = "Simulated seconds per script (default: the world's time limit, or 20).")
    Double duration;

    @Option(names = "--world", paramLabel = "WORLD.xml",
            description = "Race in this world (examples/worlds), each robot from the world's start, ranked by score.")
    Path world;

    @Option(names = "--tick", paramLabel = "SECONDS", defaultValue = "0.01", description = "Scheduler tick (default ${DEFAULT-VALUE}).")
    double tick;

    @Spec
    CommandSpec spec;

    private record Entry(String script, String robot, SimMetrics metrics, String problem) {
    }

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        List<Entry> entries = new ArrayList<>();
        java.io.PrintStream errStream = new java.io.PrintStream(new org.parpe.cli.terminal.WriterStream(err), true,
                java.nio.charset.StandardCharsets.UTF_8);
        World scene;
        try {
            scene = world == null ? null : SimOptions.readWorld(world, errStream);
            if (duration == null) {
                duration = scene == null ? 20 : scene.timeLimit();
            }
            if (!(duration > 0)) {
                throw new UsageException(CliMsg.DURATION_NOT_POSITIVE.text(duration));
            }
            ClockOptions.check(tick, duration);
            for (Path f : files) {
                Inputs.check(f);
            }
            for (Path f : files) {
                entries.add(race(f, err, errStream, scene));
            }
        } catch (UsageException u) {
            err.println("parpe: " + u.getMessage());
            return 2;
        }
        // The standard robots all head towards +x: ranked by how far they got that way (in a world
        // by score first), as far as the table shows it; equal ones keep the command line's order.
        entries.sort(Comparator.comparing((Entry e) -> e.metrics() == null).thenComparing(RaceCommand::shown, Arrays::compare));
        print(out, entries, scene != null);
        out.flush();
        return entries.stream().anyMatch(e -> e.metrics() == null) ? 1 : 0;
    }

    private Entry race(Path file, PrintWriter err, java.io.PrintStream errStream, World scene) throws UsageException {
        LoadResult r = ScriptLoader.load(file, Map.of());
        for (Diagnostic d : r.diagnostics()) {
            err.println(d.format());
        }
        if (r.program() == null || r.program().main() == null) {
            return new Entry(file.toString(), "", null, (r.program() == null ? CliMsg.SCRIPT_ERRORS : CliMsg.NO_MAIN).text());
        }
        String robot = sim != null ? sim : SimTarget.autoSpec(r.program());
        try (Simulator s = SimOptions.create(robot, r.program().moduleIds(), errStream, scene)) {
            RunOutcome outcome = SimRun.run(r.program(), s, duration, tick, d -> err.println(d.format()));
            if (outcome.status() == RunOutcome.Status.ERROR) {
                return new Entry(file.toString(), robot, null, CliMsg.RUN_TIME_ERROR.text());
            }
            return new Entry(file.toString(), robot, s.metrics(), "");
        }
    }

    /**
     * What an entry is ranked by, as the table prints it (the score to 0.1, forwards to the
     * millimetre), best first: entries equal in it tie.
     */
    private static double[] shown(Entry e) {
        if (e.metrics() == null) {
            return new double[0];
        }
        double score = e.metrics().score() == null ? 0 : e.metrics().score().score();
        return new double[] {-printed("%.1f", score) + 0.0, -printed("%.3f", e.metrics().dx()) + 0.0}; // + 0.0: no -0
    }

    private static double printed(String format, double value) {
        return Double.parseDouble(String.format(Locale.ROOT, format, value));
    }

    private static void print(PrintWriter out, List<Entry> entries, boolean scored) {
        int width = Math.max(6, entries.stream().mapToInt(e -> e.script().length()).max().orElse(6));
        int robotWidth = Math.max(5, entries.stream().mapToInt(e -> e.robot().length()).max().orElse(5));
        String columns = "%-4s  %-" + width + "s  %-" + robotWidth + "s  %11s  %12s  %11s  %13s";
        out.println(String.format(Locale.ROOT, columns, CliMsg.RANK.text(), CliMsg.SCRIPT.text(), CliMsg.ROBOT.text(),
                CliMsg.FORWARD_M.text(), CliMsg.DISTANCE_M.text(), CliMsg.SPEED_MPS.text(), CliMsg.MAX_TILT.text())
                + (scored ? String.format(Locale.ROOT, "  %10s  %s", CliMsg.SCORE.text(), CliMsg.PARTS.text()) : ""));
        int rank = 0;
        for (int i = 0; i < entries.size(); i++) {
            Entry e = entries.get(i);
            // standard competition ranking: a tie shares its rank, the next skips (1, 1, 3)
            rank = i > 0 && Arrays.equals(shown(e), shown(entries.get(i - 1))) ? rank : i + 1;
            if (e.metrics() == null) {
                out.println(String.format(Locale.ROOT, "%-4s  %-" + width + "s  %-" + robotWidth + "s  %s", "-",
                        e.script(), e.robot(), e.problem()));
            } else {
                out.println(String.format(Locale.ROOT, "%-4d  %-" + width + "s  %-" + robotWidth
                        + "s  %11.3f  %12.3f  %11.4f  %13.1f", rank, e.script(), e.robot(), e.metrics().dx(),
                        e.metrics().distance(), e.metrics().speed(), e.metrics().maxTiltDeg())
                        + (scored ? String.format(Locale.ROOT, "  %10.1f  %s", e.metrics().score().score(),
                                e.metrics().score().inWords()) : ""));
            }
        }
    }
}
