package org.parpe.cli.sweep;

import org.parpe.cli.text.CliMsg;
import java.io.PrintWriter;
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
import org.parpe.sim.sweep.Constraints;
import org.parpe.sim.sweep.Evaluation;
import org.parpe.sim.sweep.Evaluator;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.OptimizationResult;
import org.parpe.sim.sweep.OptimizeSpec;
import org.parpe.sim.sweep.Optimizer;
import org.parpe.sim.sweep.ParameterDefaults;
import org.parpe.sim.sweep.SweepException;
import org.parpe.sim.sweep.SweepListener;
import org.parpe.sim.sweep.SweepRow;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code parpe optimize}: searches the script's parameters within their {@code min}/{@code max}
 * for the best gait with CMA-ES, prints the best values and writes a copy of the script with
 * them as defaults, plus the convergence plot.
 */
@Command(name = "optimize", mixinStandardHelpOptions = true,
        description = "Search the script's parameters (those with a min and a max) for the best gait with CMA-ES on"
                + " the simulator; print the best values and write a copy of the script with them as defaults.")
public final class OptimizeCommand extends SimSweepCommand {
    @Option(names = "--objective", paramLabel = "NAME", defaultValue = "forward-speed",
            description = "What to maximise: forward-speed, speed, forward, distance, score (with --world) (default ${DEFAULT-VALUE}).")
    String objective;

    @Option(names = "--budget", paramLabel = "RUNS", defaultValue = "500", description = "The most simulations (default ${DEFAULT-VALUE}).")
    int budget;

    @Option(names = "--starts", paramLabel = "N", defaultValue = "4", description = "Independent CMA-ES searches sharing the"
            + " budget, run in parallel (default ${DEFAULT-VALUE}); the result depends on it, not on --jobs.")
    int starts;

    @Option(names = "--max-tilt", paramLabel = "DEGREES", description = "Only accept gaits whose robot never tilts more than this.")
    Double maxTilt;

    @Option(names = "--not-fallen", description = "Only accept gaits whose robot does not fall over (see --fall-tilt).")
    boolean notFallen;

    @Option(names = "--out", paramLabel = "FILE.xml", description = "The optimised script (default: FILE-optimised.xml"
            + " beside FILE; never FILE itself).")
    String out;

    @Option(names = "--force", description = "Replace an existing FILE-optimised.xml (the default --out).")
    boolean force;

    @Option(names = "--plot", paramLabel = "FILE.png", description = "The convergence plot (default: --out with -convergence.png).")
    String plot;

    @Override
    String kept() {
        return CliMsg.KEPT_BEST.text();
    }

    @Override
    int execute(PrintWriter stdout, PrintWriter err, Cancellation cancel) throws Exception {
        Objective goal = options.objective(objective);
        if (maxTilt != null && !(maxTilt >= 0 && maxTilt <= 180)) {
            throw new UsageException(CliMsg.MAX_TILT_RANGE.text(maxTilt));
        }
        Evaluator ev = options.evaluator(file, err);
        if (ev == null) {
            return 1;
        }
        Constraints constraints = new Constraints(maxTilt == null ? Double.POSITIVE_INFINITY : maxTilt, notFallen);
        Optimizer optimizer = new Optimizer(ev, new OptimizeSpec(goal, constraints, budget, starts, options.seed));
        List<Path> inputs = new ArrayList<>(List.of(file));
        options.addInputs(inputs);
        String script = out != null ? out : sibling(file, "-optimised.xml");
        OutputPlan plan = OutputFile.plan(inputs);
        // a name PARPE chose replaces nothing unless the user says so: it may be a hand-edited earlier result
        OutputFile xml = OutputFile.of(plan, "--out", script, out != null || force ? OutputPlan.Existing.REPLACE
                : OutputPlan.Existing.KEEP, CliMsg.NAME_IT_OR_FORCE.text());
        String base = script.toLowerCase(Locale.ROOT).endsWith(".xml") ? script.substring(0, script.length() - 4) : script;
        OutputFile png = OutputFile.of(plan, "--plot", plot != null ? plot : base + "-convergence.png");
        ProgressBar bar = new ProgressBar(err, SweepListener.NONE);
        OptimizationResult result = optimizer.run(options.jobs(), bar, cancel);
        bar.clear();
        if (result.evaluations().isEmpty()) {
            return 0;
        }
        String title = CliMsg.CONVERGENCE_TITLE.text(options.runsOf(file), result.evaluations().size(),
                Numbers.format(options.duration));
        if (cancel.cancelled()) {
            // AWT cannot start while the JVM shuts down (Ctrl-C): the script is written, the plot is not.
            err.println("parpe: " + CliMsg.NO_CONVERGENCE_PLOT.text());
            return report(stdout, err, result, optimizer.space().axes(), ev, xml, null);
        }
        png.write(o -> Plots.convergence(o, title, result));
        return report(stdout, err, result, optimizer.space().axes(), ev, xml, png);
    }

    private int report(PrintWriter stdout, PrintWriter err, OptimizationResult result, List<Axis> searched,
                       Evaluator ev, OutputFile xml, OutputFile png) throws UsageException, SweepException {
        Objective goal = result.objective();
        List<Evaluation> all = result.evaluations();
        Evaluation first = result.starts().get(0).isEmpty() ? null : result.starts().get(0).get(0);
        if (result.best().isEmpty()) {
            err.println("parpe: " + result.bestIgnoringConstraints().map(e -> CliMsg.NONE_MET_CONSTRAINTS_BEST.text(goal.id(),
                    String.format(Locale.ROOT, "%.4f", e.score()), String.format(Locale.ROOT, "%.1f", e.row().maxTiltDeg())))
                    .orElse(CliMsg.NONE_MET_CONSTRAINTS.text()));
            if (png != null) {
                err.println("parpe: " + CliMsg.CONVERGENCE_PLOT_IN.text(png));
            }
            return 1;
        }
        Evaluation best = result.best().get();
        stdout.println((result.cancelled() ? CliMsg.OPTIMUM_STOPPED : CliMsg.OPTIMUM).text(goal.id(),
                String.format(Locale.ROOT, "%.4f", best.score()), all.size()));
        if (first != null && first.row().values().equals(ev.parameters().stream().filter(p -> first.row().values()
                .containsKey(p.name())).collect(java.util.stream.Collectors.toMap(p -> p.name(), p -> p.value())))) {
            stdout.println((first.feasible() ? CliMsg.OWN_VALUES : CliMsg.OWN_VALUES_MISS).text(
                    String.format(Locale.ROOT, "%.4f", first.score())));
        }
        printBest(stdout, best.row(), searched);
        xml.write(ParameterDefaults.rewrite(file, ev.text(), ev.parameters(), best.row().values()));
        err.println("parpe: " + (png == null ? CliMsg.WROTE_OPTIMISED.text(xml) : CliMsg.WROTE_OPTIMISED_PLOT.text(xml, png)));
        return 0;
    }

    /**
     * The best run's values, each at an end of its range flagged (the best may lie beyond it),
     * what the robot did and, in a world, the score's parts.
     */
    private static void printBest(PrintWriter stdout, SweepRow best, List<Axis> searched) {
        for (Axis a : searched) {
            double v = best.values().get(a.name());
            String bound = a.atBound(v);
            stdout.println("  " + a.name() + " = " + Numbers.format(v) + (bound.isEmpty() ? "" : "  ("
                    + (v == a.hi() ? CliMsg.AT_MAX : CliMsg.AT_MIN).text(bound) + ")"));
        }
        stdout.println("  (" + CliMsg.BEST_DID.text(String.format(Locale.ROOT, "%.3f", best.distance()),
                String.format(Locale.ROOT, "%.3f", best.forward()), String.format(Locale.ROOT, "%.1f", best.maxTiltDeg()),
                (best.fell() ? CliMsg.YES : CliMsg.NO).text()) + ")");
        if (best.parts() != null) {
            stdout.println("  (" + CliMsg.SCORE_PARTS.text(best.parts().inWords()) + ")");
        }
        stdout.flush();
    }

    private static String sibling(Path file, String suffix) {
        String name = file.getFileName().toString();
        String stem = name.toLowerCase(Locale.ROOT).endsWith(".xml") ? name.substring(0, name.length() - 4) : name;
        Path parent = file.getParent();
        return (parent == null ? Path.of(stem + suffix) : parent.resolve(stem + suffix)).toString();
    }
}
