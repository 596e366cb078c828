package org.parpe.cli.sweep;

import org.parpe.cli.text.CliMsg;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.parpe.cli.options.ClockOptions;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.ParamValues;
import org.parpe.cli.options.UsageException;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.xml.InputFiles;
import org.parpe.sim.SimTarget;
import org.parpe.sim.sweep.Evaluator;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.SweepException;
import picocli.CommandLine.Option;

/** The options {@code sweep} and {@code optimize} share: robot, duration, fixed parameters, threads, seed. */
public class SimSweepOptions {
    @Option(names = "--sim", paramLabel = "ROBOT", defaultValue = SimTarget.AUTO,
            description = "GENERATOR[:key=value,...] or CONFIG.xml (default: the robot that fits the script,"
                    + " as 'parpe race' picks it).")
    String sim;

    @Option(names = "--duration", paramLabel = "SECONDS", defaultValue = "20",
            description = "Simulated seconds per run (default ${DEFAULT-VALUE}).")
    double duration;

    @Option(names = "--tick", paramLabel = "SECONDS", defaultValue = "0.01", description = "Scheduler tick (default ${DEFAULT-VALUE}).")
    double tick;

    @Option(names = "--param", paramLabel = "NAME=VALUE", description = "Keep a parameter at this value in every run (repeatable).")
    List<String> params = new java.util.ArrayList<>();

    @Option(names = "--jobs", paramLabel = "N", description = "Simulations at once (default: the number of cores, ${sys:parpe.cores}).")
    Integer jobs;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "0", description = "Seed of the random draws and of rand() (default ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--world", paramLabel = "WORLD.xml",
            description = "Run every run in this world (examples/worlds) and record its score (objective 'score').")
    Path world;

    @Option(names = "--fall-tilt", paramLabel = "DEGREES", defaultValue = "90",
            description = "A robot whose tilt passes this angle has fallen over (default ${DEFAULT-VALUE}).")
    double fallTilt;

    static {
        System.setProperty("parpe.cores", Integer.toString(Runtime.getRuntime().availableProcessors()));
    }

    /** What every run is, for a plot's title: {@code snake.xml on snake:n=8 in race-track.xml}. */
    String runsOf(Path file) {
        return world == null ? CliMsg.RUNS_ON.text(file.getFileName(), sim.trim())
                : CliMsg.RUNS_ON_IN.text(file.getFileName(), sim.trim(), world.getFileName());
    }

    /** The objective named by {@code --objective}; {@code score} needs {@code --world}. */
    Objective objective(String id) throws UsageException {
        return objective(id, world != null);
    }

    /** The objective named by {@code --objective}; {@code score} only where runs are {@code scored} (in a world). */
    static Objective objective(String id, boolean scored) throws UsageException {
        Objective o = Objective.byId(id);
        if (o == null) {
            throw new UsageException(CliMsg.BAD_OBJECTIVE.text(Objective.ids(), id));
        }
        if (o == Objective.SCORE && !scored) {
            throw new UsageException(CliMsg.SCORE_NEEDS_WORLD.text());
        }
        return o;
    }

    /** The number of threads: {@code --jobs}, or every core. */
    int jobs() throws UsageException {
        if (jobs == null) {
            return Runtime.getRuntime().availableProcessors();
        }
        if (jobs < 1 || jobs > 1024) {
            throw new UsageException(CliMsg.JOBS_RANGE.text(jobs));
        }
        return jobs;
    }

    /**
     * Loads {@code file} for runs: script errors are printed (all of them) and end with exit
     * code 1 ({@code null} returned), bad options throw a usage error.
     */
    Evaluator evaluator(Path file, PrintWriter err) throws UsageException {
        ClockOptions.check(tick, duration);
        if (!(duration > 0)) {
            throw new UsageException(CliMsg.DURATION_NOT_POSITIVE.text(duration));
        }
        if (!(fallTilt >= 0 && fallTilt <= 180)) {
            throw new UsageException(CliMsg.FALL_TILT_RANGE.text(fallTilt));
        }
        Inputs.check(file);
        if (world != null) {
            Inputs.check(world);
        }
        Map<String, Double> fixed = ParamValues.parse(params);
        LoadResult r = ScriptLoader.load(file, fixed);
        r.diagnostics().forEach(d -> err.println(d.format()));
        if (r.program() == null) {
            return null;
        }
        if (!r.parameterErrors().isEmpty()) {
            r.parameterErrors().forEach(d -> err.println(d.format()));
            throw new UsageException(CliMsg.BAD_PARAMS_ABOVE.text());
        }
        try {
            String text = InputFiles.readText(file);
            return Evaluator.load(new Evaluator.Settings(file, text, fixed, sim.trim(), duration, tick, fallTilt,
                    world));
        } catch (IOException e) {
            throw new UsageException(CliMsg.CANNOT_READ.text(file, e.getMessage()));
        } catch (SweepException e) {
            throw new UsageException(e.getMessage());
        }
    }

    /** The input files besides the script: a robot configuration file named by {@code --sim}. */
    void addInputs(List<Path> inputs) {
        if (world != null) {
            inputs.add(world);
        }
        try {
            if (Files.isRegularFile(Path.of(sim.trim()))) {
                inputs.add(Path.of(sim.trim()));
            }
        } catch (java.nio.file.InvalidPathException notAFile) {
            // a generator spec such as snake:n=8 need not be a valid path
        }
    }
}
