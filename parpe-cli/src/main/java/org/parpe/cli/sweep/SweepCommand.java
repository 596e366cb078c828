package org.parpe.cli.sweep;

import org.parpe.cli.text.CliMsg;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.parpe.cli.options.OutputFile;
import org.parpe.core.io.OutputPlan;
import org.parpe.cli.options.UsageException;
import org.parpe.core.lang.Numbers;
import org.parpe.sim.sweep.Axis;
import org.parpe.sim.sweep.Cancellation;
import org.parpe.sim.sweep.Evaluator;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.Sweep;
import org.parpe.sim.sweep.SweepCsv;
import org.parpe.sim.sweep.SweepListener;
import org.parpe.sim.sweep.SweepResult;
import org.parpe.sim.sweep.SweepRow;
import org.parpe.sim.sweep.SweepSpec;
import org.parpe.sim.sweep.VarySpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code parpe sweep}: runs a script with every combination of the varied parameters (or random
 * ones) on fresh simulated robots, on every core, and writes one CSV row per run plus a plot.
 */
@Command(name = "sweep", mixinStandardHelpOptions = true, description = "Run a script with every combination of"
        + " parameter values (or --random ones) on fresh simulated robots, in parallel; write one CSV row per run"
        + " and a plot of the objective over the parameters.")
public final class SweepCommand extends SimSweepCommand {
    @Option(names = "--vary", paramLabel = "NAME=RANGE", description = "A parameter to vary: NAME=A..B (integers),"
            + " NAME=A..B:K (K values), NAME=V1,V2,... (repeatable). With --random and no --vary: every parameter"
            + " with a min and a max, over [min, max].")
    List<String> vary = new ArrayList<>();

    @Option(names = "--random", paramLabel = "COUNT", description = "Draw COUNT random combinations (with --seed) instead of the whole grid.")
    Integer random;

    @Option(names = "--repeat", paramLabel = "K", defaultValue = "1",
            description = "Run each combination K times, with rand() seeds SEED..SEED+K-1 (default ${DEFAULT-VALUE}).")
    int repeat;

    @Option(names = "--out", paramLabel = "FILE.csv|-", required = true, description = "Where to write the CSV ('-': standard output).")
    String out;

    @Option(names = "--plot", paramLabel = "FILE.png", description = "Where to draw the plot (default: --out with .png;"
            + " none for a shard or standard output).")
    String plot;

    @Option(names = "--objective", paramLabel = "NAME", defaultValue = "forward-speed",
            description = "What the plot and the summary rank by: forward-speed, speed, forward, distance, score (with --world) (default ${DEFAULT-VALUE}).")
    String objective;

    @Option(names = "--count-fallen", description = "Let a run whose robot fell over (see --fall-tilt) be the best;"
            + " by default a fallen run is never the best, in the summary or in the plot.")
    boolean countFallen;

    @Option(names = "--shard", paramLabel = "K/N", description = "Run only the K-th of N equal shares of the runs (1 <= K <= N);"
            + " join the shards' files with 'parpe merge'.")
    String shard;

    @Override
    String kept() {
        return CliMsg.KEPT_FINISHED.text();
    }

    @Override
    int execute(PrintWriter stdout, PrintWriter err, Cancellation cancel) throws Exception {
        Objective goal = options.objective(objective);
        int[] share = shard();
        Evaluator ev = options.evaluator(file, err);
        if (ev == null) {
            return 1;
        }
        List<Axis> axes = new ArrayList<>();
        for (String v : vary) {
            axes.add(VarySpec.parse(v, ev.parameters()));
        }
        if (axes.isEmpty() && random != null) {
            axes = SweepSpec.declaredSpace(ev.parameters(), ev.fixed().keySet());
        }
        if (random != null && random < 1) {
            throw new UsageException(CliMsg.RANDOM_AT_LEAST_ONE.text(random));
        }
        Sweep sweep = new Sweep(ev, random == null ? SweepSpec.grid(axes, repeat, options.seed)
                : SweepSpec.random(axes, random, repeat, options.seed));
        int total = sweep.spec().size();
        int[] range = share == null ? new int[] {0, total} : SweepSpec.shard(total, share[0], share[1]);
        List<Path> inputs = new ArrayList<>(List.of(file));
        options.addInputs(inputs);
        OutputPlan plan = OutputFile.plan(inputs);
        OutputFile csv = OutputFile.ofOptional(plan, "--out", out);
        OutputFile plotTarget = plotFile(plan, share != null);
        if (cancel.cancelled()) {
            return 0;
        }
        SweepResult result = write(sweep, share, range, csv, stdout, err, cancel);
        OutputFile png = plotTarget;
        if (png != null && cancel.cancelled()) {
            // AWT cannot start while the JVM shuts down (Ctrl-C): the rows are safe, the plot is not drawn.
            err.println("parpe: " + CliMsg.NO_PLOT_DRAWN.text());
            png = null;
        }
        if (png != null) {
            String title = CliMsg.PLOT_TITLE.text(CliMsg.RUNS_OF_SECONDS.text(options.runsOf(file),
                    Numbers.format(options.duration)), result.rows().size());
            png.write(o -> Plots.sweep(o, title, sweep.spec().axes(), result.rows(), goal, countFallen));
        }
        summary(err, result, range[1] - range[0], goal, sweep.spec().axes(), png);
        return 0;
    }

    /**
     * Runs the sweep's share {@code range}, writing the header and each row as it comes; a
     * shard ({@code share}) is framed and written through a {@link ShardFile}.
     */
    private SweepResult write(Sweep sweep, int[] share, int[] range, OutputFile csv, PrintWriter stdout,
                              PrintWriter err, Cancellation cancel) throws UsageException {
        int total = sweep.spec().size();
        ShardFile shardFile = share != null && csv != null ? ShardFile.of(out) : null;
        SweepResult result = null;
        boolean whole = false;
        Writer w = null;
        try {
            w = shardFile != null ? shardFile.open() : csv != null ? csv.openWriter() : null;
            Writer target = w != null ? w : stdout;
            if (share != null) {
                target.write(SweepCsv.shardStart(share[0], share[1], range[0], range[1], total) + "\n");
            }
            boolean scored = options.world != null;
            target.write(SweepCsv.header(sweep.spec().axes(), scored) + "\n");
            ProgressBar bar = new ProgressBar(err, rows(target, w == null ? stdout : null, total, scored, share != null));
            result = sweep.run(range[0], range[1], options.jobs(), bar, cancel);
            bar.clear();
            if (share != null && !result.cancelled()) {
                target.write(SweepCsv.shardEnd(share[0], share[1]) + "\n");
            }
            target.flush();
            if (w == null && stdout.checkError()) {
                throw new IOException(CliMsg.STDOUT_CLOSED.text());
            }
            if (w != null) {
                w.close(); // puts the file in place, also after Ctrl-C (with the rows finished in order)
            }
            whole = true;
        } catch (java.io.UncheckedIOException | IOException e) {
            String why = e instanceof java.io.UncheckedIOException u ? u.getCause().getMessage() : e.getMessage();
            throw new UsageException(csv == null ? CliMsg.CANNOT_WRITE_STDOUT.text(why)
                    : shardFile != null ? CliMsg.CANNOT_WRITE_OUT.text(out, why) : why);
        } finally {
            OutputFile.abort(w); // after a failure (a full disk, or of PARPE itself) the old file stays, no temporary one
            if (shardFile != null && !(whole && !result.cancelled())) {
                shardFile.release(); // a whole shard lets go once it is in place (commit)
            }
        }
        if (shardFile != null && result.cancelled()) {
            err.println("parpe: " + CliMsg.SHARD_UNFINISHED.text(share[0], share[1], result.rows().size(), shardFile.partial()));
        } else if (shardFile != null) {
            try {
                shardFile.commit();
            } catch (IOException e) {
                throw new UsageException(CliMsg.CANNOT_WRITE_OUT.text(out, e.getMessage()));
            }
        }
        return result;
    }

    /**
     * Writes each finished row to {@code target} as a CSV line, flushed at once for a shard (a
     * killed task keeps it); a write to {@code stdout} (null for a file) that fails is an error.
     */
    private static SweepListener rows(Writer target, PrintWriter stdout, int total, boolean scored, boolean shard) {
        return new SweepListener() {
            @Override
            public void row(SweepRow row) {
                try {
                    target.write(SweepCsv.line(row, total, scored) + "\n");
                    if (shard) {
                        target.flush(); // each finished row reaches the file: a killed task keeps it
                    }
                    if (stdout != null && stdout.checkError()) {
                        throw new IOException(CliMsg.STDOUT_CLOSED.text());
                    }
                } catch (IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }
        };
    }

    private void summary(PrintWriter err, SweepResult result, int expected, Objective goal, List<Axis> axes,
                         OutputFile png) {
        List<SweepRow> rows = result.rows();
        long failed = rows.stream().filter(r -> !r.ok()).count();
        long fell = rows.stream().filter(SweepRow::fell).count();
        err.println("parpe: " + (result.cancelled() ? CliMsg.SWEEP_SUMMARY_STOPPED : CliMsg.SWEEP_SUMMARY).text(rows.size(),
                expected, failed, fell));
        java.util.Optional<SweepRow> best = SweepResult.best(rows, goal, SweepResult.rule(countFallen));
        best.ifPresent(b -> err.println("parpe: " + (b.fell() ? CliMsg.SWEEP_BEST_FELL : CliMsg.SWEEP_BEST).text(goal.id(),
                String.format(Locale.ROOT, "%.4f", goal.of(b)), values(b), b.point().index())));
        best.ifPresent(b -> axes.forEach(a -> {
            String bound = a.atBound(b.values().get(a.name()));
            if (!bound.isEmpty()) {
                err.println("parpe: " + CliMsg.BEST_AT_BOUND.text(a.name() + "=" + Numbers.format(b.values().get(a.name())), bound));
            }
        }));
        if (best.isEmpty() && !rows.isEmpty()) {
            err.println("parpe: " + (countFallen ? CliMsg.NO_BEST_RUN : CliMsg.NO_BEST_RUN_FELL).text());
        }
        if (png != null) {
            err.println("parpe: " + CliMsg.PLOT_IN.text(png));
        }
    }

    private static String values(SweepRow row) {
        List<String> parts = new ArrayList<>();
        row.values().forEach((k, v) -> parts.add(k + "=" + Numbers.format(v)));
        return String.join(" ", parts);
    }

    private int[] shard() throws UsageException {
        return shard == null ? null : parseShard(shard);
    }

    /** K and N of {@code --shard K/N} (sweep's and grade's): whole numbers, 1 <= K <= N <= 999999. */
    public static int[] parseShard(String shard) throws UsageException {
        String[] kn = shard.trim().split("/", -1);
        if (kn.length != 2 || !kn[0].matches("\\d+") || !kn[1].matches("\\d+")) {
            throw new UsageException(CliMsg.SHARD_SYNTAX.text(shard));
        }
        // a shard's first line holds K and N in at most six digits (SweepCsv.shardStart)
        if (kn[1].replaceFirst("^0+(?=.)", "").length() > 6) {
            throw new UsageException(CliMsg.SHARD_N_TOO_LARGE.text(shard.trim(), kn[1]));
        }
        if (kn[0].replaceFirst("^0+(?=.)", "").length() > 6) {
            throw new UsageException(CliMsg.SHARD_K_RANGE.text(shard.trim(), kn[0]));
        }
        int k = Integer.parseInt(kn[0]);
        int n = Integer.parseInt(kn[1]);
        if (n < 1 || k < 1 || k > n) {
            throw new UsageException(CliMsg.SHARD_K_N.text(shard));
        }
        return new int[] {k, n};
    }

    private OutputFile plotFile(OutputPlan plan, boolean sharded) throws UsageException {
        if (plot != null) {
            return OutputFile.of(plan, "--plot", plot);
        }
        if (sharded || out.equals("-")) {
            return null;
        }
        String base = out.toLowerCase(Locale.ROOT).endsWith(".csv") ? out.substring(0, out.length() - 4) : out;
        return OutputFile.of(plan, "--plot", base + ".png");
    }
}
