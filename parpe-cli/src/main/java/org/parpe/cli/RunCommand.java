package org.parpe.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.parpe.cli.hw.HardwareOptions;
import org.parpe.cli.text.CliMsg;
import org.parpe.cli.options.ClockOptions;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.OutputFile;
import org.parpe.cli.options.ParamValues;
import org.parpe.cli.options.UsageException;
import org.parpe.cli.sim.SimOptions;
import org.parpe.cli.terminal.FoldedDiagnostics;
import org.parpe.cli.terminal.InterruptHook;
import org.parpe.cli.terminal.LoadReport;
import org.parpe.cli.terminal.Progress;
import org.parpe.cli.terminal.WriterStream;
import org.parpe.core.io.OutputPlan;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.core.run.Pacer;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.Stimulus;
import org.parpe.core.run.TargetException;
import org.parpe.core.run.WallClockPacer;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code parpe run}: runs a script headless, on the simulator, on hardware, or both (PARSL.md §11). */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = "Run a PARSL script. Without --sim or --port only setpoints are computed, as fast as possible.")
final class RunCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE", descriptionKey = "file", description = "The PARSL script.")
    Path file;

    @Option(names = "--duration", paramLabel = "SECONDS", description = "Stop after this much simulated time (default: when <main> ends).")
    Double duration;

    @Option(names = "--tick", paramLabel = "SECONDS", defaultValue = "0.01", description = "Scheduler tick (default ${DEFAULT-VALUE}).")
    double tick;

    @Option(names = "--param", paramLabel = "NAME=VALUE", description = "Set a parameter (repeatable).")
    List<String> params = new ArrayList<>();

    @Option(names = "--stimulus", paramLabel = "FILE", description = "Timed control and sensor assignments.")
    Path stimulus;

    @Option(names = "--trace", paramLabel = "FILE|-", description = "Write the CSV trace to FILE or '-' for standard output.")
    String trace;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "0", description = "Seed of rand() (default ${DEFAULT-VALUE}).")
    long seed;

    @Mixin
    SimOptions sim = new SimOptions();

    @Mixin
    HardwareOptions hardware = new HardwareOptions();

    @Spec
    CommandSpec spec;

    private OutputFile traceFile;

    @Override
    public Integer call() throws Exception {
        return execute(errStream());
    }

    private PrintStream errStream() {
        return new PrintStream(new WriterStream(spec.commandLine().getErr()), true, StandardCharsets.UTF_8);
    }

    /** The options of the clock, and the script and stimulus files, checked before anything is read. */
    private void checkInputs() throws Exception {
        ClockOptions.check(tick, duration);
        Inputs.check(file);
        if (stimulus != null) {
            Inputs.check(stimulus);
        }
    }

    private int execute(PrintStream err) throws Exception {
        checkInputs();
        LoadResult r = ScriptLoader.load(file, ParamValues.parse(params));
        int refused = LoadReport.exitCode(r, err::println);
        if (refused != 0) {
            return refused;
        }
        Program program = r.program();
        if (program.main() == null) {
            err.println(file + ": warning: " + CliMsg.NOTHING_TO_RUN.text());
            return 0;
        }
        checkOutputs(r);
        sim.noteDeclaredWorld(file, err);
        boolean worldLimit = duration == null && sim.world(err) != null;
        if (worldLimit) {
            duration = sim.world(err).timeLimit(); // a world's challenge lasts its time limit
        }
        if (duration == null) {
            err.println("parpe: " + CliMsg.NO_DURATION.text());
        }
        RunOptions options = new RunOptions(tick, seed, stimuli(program));
        // Equal warnings of the run (a bus warning said again and again) fold as in the IDE.
        FoldedDiagnostics diagnostics = new FoldedDiagnostics(err::println);
        Run.Builder builder = Run.builder(program, options, diagnostics);
        if (duration != null) {
            builder.duration(duration);
        }
        Writer out;
        try {
            sim.configure(builder, err);
            hardware.configure(builder, err);
            out = traceWriter();
        } catch (TargetException e) {
            builder.abandon();
            e.diagnostics().forEach(d -> err.println(d.format()));
            if (e.diagnostics().size() > 1) {
                err.println("parpe: " + e.getMessage());
            }
            return 2;
        } catch (UsageException e) {
            builder.abandon();
            throw e;
        }
        if (out != null) {
            builder.trace(out);
        }
        builder.observer(Progress.forStderr(err, duration == null ? Double.POSITIVE_INFINITY : duration));
        builder.pacer(sim.realtime() || builder.realtimeRequired() ? new WallClockPacer(1) : Pacer.NONE);
        RunOutcome outcome = execute(builder.build(), out, diagnostics);
        if (outcome.status() == RunOutcome.Status.STOPPED) {
            err.println("parpe: " + CliMsg.STOPPED_AT.text(String.format(Locale.ROOT, "%.3f", outcome.time())));
        } else if (worldLimit && outcome.status() == RunOutcome.Status.COMPLETED && outcome.time() >= duration - 1e-6) {
            err.println("parpe: " + CliMsg.WORLD_TIME_LIMIT.text(org.parpe.core.lang.Numbers.format(duration), sim.world(err).name()));
        }
        return sim.outputsWritten(outcome.status() == RunOutcome.Status.ERROR ? 3 : 0);
    }

    /**
     * Runs {@code run} until it ends or Ctrl-C stops it, then replaces the trace file {@code out}
     * (also after a run-time error: its rows are kept) or flushes standard output.
     */
    private RunOutcome execute(Run run, Writer out, FoldedDiagnostics diagnostics) throws UsageException {
        boolean toStdout = "-".equals(trace);
        RunOutcome outcome;
        try (InterruptHook hook = new InterruptHook(run::requestStop, 3)) {
            outcome = run.execute();
            if (out != null && !toStdout) {
                out.close(); // replaces the trace file, also after a run-time error (its rows are kept)
            } else if (out != null) {
                out.flush();
            }
        } catch (UncheckedIOException e) {
            // an output that failed while the run wrote it (full disk): OutputFile named it
            throw new UsageException(e.getCause().getMessage());
        } catch (IOException e) {
            throw new UsageException(e.getMessage());
        } finally {
            OutputFile.abort(out); // after a failure of PARPE itself no temporary trace file is left; after close, nothing
            diagnostics.finish();
        }
        return outcome;
    }

    private List<Stimulus> stimuli(Program program) throws UsageException {
        return Inputs.stimuli(stimulus, program);
    }

    /** Refuses outputs that would replace a directory, a device or an input, before the run starts. */
    private void checkOutputs(LoadResult r) throws UsageException {
        List<Path> inputs = new ArrayList<>(r.files());
        if (stimulus != null) {
            inputs.add(stimulus);
        }
        sim.addInputs(inputs);
        hardware.addInputs(inputs);
        OutputPlan plan = OutputFile.plan(inputs);
        traceFile = OutputFile.ofOptional(plan, "--trace", trace);
        sim.checkOutputs(plan);
    }

    private Writer traceWriter() throws UsageException {
        if (trace == null) {
            return null;
        }
        if (trace.equals("-")) {
            return new BufferedWriter(new OutputStreamWriter(System.out, StandardCharsets.UTF_8), 1 << 16);
        }
        return traceFile.openWriter();
    }
}
