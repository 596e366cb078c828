package org.parpe.cli.sim;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.parpe.cli.OutputFile;
import org.parpe.cli.RunSetup;
import org.parpe.cli.RunTarget;
import org.parpe.cli.UsageException;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.run.RunOutcome;
import org.parpe.sim.SimMetrics;
import org.parpe.sim.Simulator;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;
import picocli.CommandLine.Option;

/** The simulator options of {@code parpe run} ({@code --sim}, {@code --metrics}, {@code --plot}, {@code --realtime}). */
public class SimOptions implements RunTarget {
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

    private OutputFile metricsFile;
    private OutputFile plotFile;
    /** Whether writing the metrics or the plot failed (reported at once). */
    private boolean outputFailed;

    @Override
    public void configure(RunSetup setup) throws UsageException {
        if (sim == null) {
            if (metrics != null || plot != null || realtime) {
                throw new UsageException("--metrics, --plot and --realtime need --sim");
            }
            return;
        }
        Simulator simulator = create(sim, setup.program().moduleIds(), setup.err());
        setup.closeAtEnd(simulator);
        simulator.start(new org.parpe.core.run.RunInfo(setup.program(), setup.program().moduleIds(),
                setup.options().dt()));
        setup.addSink(simulator);
        setup.offerSensorSource("sim", simulator, 5);
        setup.addTraceColumns(simulator.traceColumns());
        setup.setRealtime(realtime);
        if (plot != null) {
            PlotRecorder recorder = new PlotRecorder(simulator, setup.program().moduleIds(), setup.duration(),
                    setup.options().dt());
            setup.addSink(recorder);
            setup.onFinish(o -> writePlot(recorder, setup.err()));
        }
        if (metrics != null) {
            setup.onFinish(o -> writeMetrics(simulator.metrics(), o, setup.err()));
        }
    }

    /**
     * Builds the simulator for {@code spec}, printing located problems to {@code err}; a bad spec
     * or configuration file is a usage error.
     */
    static Simulator create(String spec, int[] moduleIds, PrintStream err) throws UsageException {
        DiagnosticList diags = new DiagnosticList();
        RobotConfig config = RobotConfigs.resolve(spec, moduleIds, diags);
        if (config != null) {
            RobotConfigs.checkModules(config, moduleIds, diags);
        }
        for (Diagnostic d : diags.all()) {
            err.println(d.format());
        }
        if (config == null) {
            throw new UsageException("cannot build the simulated robot '" + spec + "' (" + diags.errorCount()
                    + " error" + (diags.errorCount() == 1 ? "" : "s") + " above)");
        }
        return new Simulator(config);
    }

    /** Adds the robot configuration file of {@code --sim}, if it names one, to the run's inputs. */
    public void addInputs(List<Path> inputs) {
        try {
            if (sim != null && Files.isRegularFile(Path.of(sim.trim()))) {
                inputs.add(Path.of(sim.trim()));
            }
        } catch (java.nio.file.InvalidPathException notAFile) {
            // a generator spec such as snake:n=8 need not be a valid path
        }
    }

    /** Checks the {@code --metrics} and {@code --plot} targets before the run starts. */
    public void checkOutputs(List<Path> inputs) throws UsageException {
        metricsFile = OutputFile.ofOptional("--metrics", metrics, inputs);
        plotFile = plot == null ? null : OutputFile.of("--plot", plot.toString(), inputs);
    }

    /** {@code code}, or 2 (a usage or I/O error) if writing the metrics or the plot failed. */
    public int outputsWritten(int code) {
        return outputFailed ? 2 : code;
    }

    private void writeMetrics(SimMetrics m, RunOutcome outcome, PrintStream err) {
        String json = m.toJson() + System.lineSeparator();
        if (metricsFile == null) {
            System.out.print(json);
            System.out.flush();
            return;
        }
        try {
            metricsFile.write(json);
        } catch (UsageException e) {
            err.println("parpe: " + e.getMessage());
            outputFailed = true;
        }
    }

    private void writePlot(PlotRecorder recorder, PrintStream err) {
        try {
            plotFile.write(new PlotWriter(recorder)::write);
        } catch (UsageException e) {
            err.println("parpe: " + e.getMessage());
            outputFailed = true;
        }
    }
}
