package org.parpe.cli.sim;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.parpe.cli.UsageException;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.TargetException;
import org.parpe.sim.SimMetrics;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;
import picocli.CommandLine.Option;

/** The simulator options of {@code parpe run} ({@code --sim}, {@code --metrics}, {@code --plot}, {@code --realtime}). */
public class SimOptions {
    @Option(names = "--sim", arity = "0..1", fallbackValue = "snake", paramLabel = "ROBOT",
            description = "Run on the physics simulator. ROBOT is GENERATOR[:key=value,...] (snake, loop, wheel,"
                    + " centipede, humanoid) or a configuration file CONFIG.xml; without ROBOT, a snake of the"
                    + " script's modules.")
    String sim;

    @Option(names = "--metrics", paramLabel = "FILE|-",
            description = "With --sim: write distance, speed and tilt as JSON to FILE or '-' for standard output.")
    String metrics;

    @Option(names = "--plot", paramLabel = "FILE.png",
            description = "With --sim: draw commanded and measured joint angles over time into a PNG image.")
    Path plot;

    @Option(names = "--realtime", description = "With --sim: pace the run to the wall clock.")
    boolean realtime;

    /** Whether {@code --realtime} was given. */
    public boolean realtime() {
        return realtime;
    }

    /**
     * Attaches the simulator to {@code run} when {@code --sim} was given, with the plot and
     * metrics it asks for ({@code duration}: the run's limit, for the plot's sampling; messages
     * about the outputs go to {@code err}).
     */
    public void configure(Run.Builder run, double duration, PrintStream err) throws UsageException, TargetException {
        if (sim == null) {
            if (metrics != null || plot != null || realtime) {
                throw new UsageException("--metrics, --plot and --realtime need --sim");
            }
            return;
        }
        SimTarget target = new SimTarget(sim);
        run.attach(target);
        Simulator simulator = target.simulator();
        if (plot != null) {
            PlotRecorder recorder = new PlotRecorder(simulator, run.program().moduleIds(), duration,
                    run.options().dt());
            run.observer(recorder);
            run.onFinish(o -> writePlot(recorder, err));
        }
        if (metrics != null) {
            run.onFinish(o -> writeMetrics(simulator.metrics(), o, err));
        }
    }

    /**
     * Builds the simulator for {@code spec} outside a run ({@code race}), printing located
     * problems to {@code err}; a bad spec or configuration file is a usage error.
     */
    static Simulator create(String spec, int[] moduleIds, PrintStream err) throws UsageException {
        try {
            return SimTarget.create(spec, moduleIds, d -> err.println(d.format()));
        } catch (TargetException e) {
            e.diagnostics().forEach(d -> err.println(d.format()));
            throw new UsageException(e.getMessage() + " above");
        }
    }

    private void writeMetrics(SimMetrics m, RunOutcome outcome, PrintStream err) {
        String json = m.toJson() + System.lineSeparator();
        if (metrics.equals("-")) {
            System.out.print(json);
            System.out.flush();
            return;
        }
        try {
            Files.writeString(Path.of(metrics), json, StandardCharsets.UTF_8);
        } catch (IOException | RuntimeException e) {
            err.println("parpe: error: cannot write metrics file '" + metrics + "': " + e.getMessage());
        }
    }

    private void writePlot(PlotRecorder recorder, PrintStream err) {
        try {
            new PlotWriter(recorder).write(plot);
        } catch (IOException | RuntimeException e) {
            err.println("parpe: error: cannot write plot '" + plot + "': " + e.getMessage());
        }
    }
}
