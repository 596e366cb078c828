package org.parpe.cli.sim;

import org.parpe.cli.text.CliMsg;
import org.parpe.core.plot.AngleRecorder;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.OutputFile;
import org.parpe.core.io.OutputPlan;
import org.parpe.cli.options.UsageException;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.TargetException;
import org.parpe.sim.SimMetrics;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;
import picocli.CommandLine.Option;

/** The simulator options of {@code parpe run} ({@code --sim}, {@code --metrics}, {@code --plot}, {@code --realtime}). */
public class SimOptions {
    @Option(names = "--sim", arity = "0..1", fallbackValue = "snake", paramLabel = "ROBOT",
            description = "Run on the physics simulator. ROBOT is GENERATOR[:key=value,...] (snake, loop, wheel,"
                    + " centipede, humanoid) or a configuration file CONFIG.xml; without ROBOT, a snake of the"
                    + " script's modules.")
    String sim;

    @Option(names = "--metrics", paramLabel = "FILE|-",
            description = "With --sim: write distance, speed and tilt (and in a world the score and its parts) as"
                    + " JSON to FILE or '-' for standard output.")
    String metrics;

    @Option(names = "--world", paramLabel = "WORLD.xml",
            description = "With --sim: put the robot in this world (examples/worlds) at its start; the run lasts the"
                    + " world's time limit unless --duration says otherwise, and --metrics gains the score.")
    Path world;

    private World loadedWorld;

    @Option(names = "--plot", paramLabel = "FILE.png",
            description = "With --sim: draw commanded and measured joint angles over time into a PNG image.")
    Path plot;

    @Option(names = "--realtime", description = "With --sim: pace the run to the wall clock.")
    boolean realtime;

    private OutputFile metricsFile;
    private OutputFile plotFile;
    /** Whether writing the metrics or the plot failed (reported at once). */
    private boolean outputFailed;

    /**
     * Tells on {@code err} that {@code script} names the world it is written for
     * ({@code <?parpe world?>}) when it runs on the simulator without {@code --world}: the
     * command line takes the world only from {@code --world}.
     */
    public void noteDeclaredWorld(Path script, PrintStream err) {
        if (sim == null || world != null) {
            return;
        }
        try {
            Path declared = WorldReader.declaredBy(script, Files.readString(script));
            if (declared != null) {
                err.println(script + ": note: " + CliMsg.WRITTEN_FOR_WORLD.text(declared));
            }
        } catch (IOException | java.io.UncheckedIOException e) {
            // the script was read a moment ago; a file gone since loses only this note
        }
    }

    /** Whether {@code --realtime} was given. */
    public boolean realtime() {
        return realtime;
    }

    /**
     * Attaches the simulator to {@code run} when {@code --sim} was given, with the plot and
     * metrics it asks for (messages about the outputs go to {@code err}).
     */
    public void configure(Run.Builder run, PrintStream err) throws UsageException, TargetException {
        if (sim == null) {
            if (metrics != null || plot != null || realtime || world != null) {
                throw new UsageException(CliMsg.NEEDS_SIM.text());
            }
            return;
        }
        SimTarget target = new SimTarget(sim, world(err));
        run.attach(target);
        Simulator simulator = target.simulator();
        if (plot != null) {
            AngleRecorder recorder = AngleRecorder.wholeRun(PlotWriter.SAMPLES).attachTo(run);
            run.onFinish(o -> writePlot(recorder, err));
        }
        if (metrics != null) {
            run.onFinish(o -> writeMetrics(simulator.metrics(), o, err));
        }
    }

    /**
     * The world of {@code --world}, read once (null without it); its problems are printed to
     * {@code err} and make a usage error.
     */
    public World world(PrintStream err) throws UsageException {
        if (world != null && loadedWorld == null) {
            loadedWorld = readWorld(world, err);
        }
        return loadedWorld;
    }

    /** Reads the world file {@code file}, printing its problems to {@code err}; with problems a usage error. */
    static World readWorld(Path file, PrintStream err) throws UsageException {
        Inputs.check(file);
        DiagnosticList found = new DiagnosticList();
        World w = WorldReader.read(file, found);
        found.all().forEach(d -> err.println(d.format()));
        if (w == null) {
            throw new UsageException(CliMsg.WORLD_HAS_ERRORS.text(file));
        }
        return w;
    }

    /**
     * Builds the simulator for {@code spec} outside a run ({@code race}), printing located
     * problems to {@code err}; a bad spec or configuration file is a usage error.
     */
    static Simulator create(String spec, int[] moduleIds, PrintStream err, World inWorld) throws UsageException {
        try {
            return SimTarget.create(spec, moduleIds, d -> err.println(d.format()), inWorld);
        } catch (TargetException e) {
            e.diagnostics().forEach(d -> err.println(d.format()));
            throw new UsageException(CliMsg.SEE_ABOVE.text(e.getMessage()));
        }
    }

    /** Adds the robot configuration file of {@code --sim}, if it names one, to the run's inputs. */
    public void addInputs(List<Path> inputs) {
        if (world != null) {
            inputs.add(world);
        }
        try {
            if (sim != null && Files.isRegularFile(Path.of(sim.trim()))) {
                inputs.add(Path.of(sim.trim()));
            }
        } catch (java.nio.file.InvalidPathException notAFile) {
            // a generator spec such as snake:n=8 need not be a valid path
        }
    }

    /** Checks the {@code --metrics} and {@code --plot} targets before the run starts. */
    public void checkOutputs(OutputPlan plan) throws UsageException {
        metricsFile = OutputFile.ofOptional(plan, "--metrics", metrics);
        plotFile = plot == null ? null : OutputFile.of(plan, "--plot", plot.toString());
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

    private void writePlot(AngleRecorder recorder, PrintStream err) {
        try {
            plotFile.write(new PlotWriter(recorder)::write);
        } catch (UsageException e) {
            err.println("parpe: " + e.getMessage());
            outputFailed = true;
        }
    }
}
