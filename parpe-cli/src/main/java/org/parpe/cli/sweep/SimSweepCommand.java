package org.parpe.cli.sweep;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.parpe.cli.terminal.InterruptHook;
import org.parpe.sim.sweep.Cancellation;
import org.parpe.sim.sweep.SweepException;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * What {@code sweep} and {@code optimize} share: a script run many times on the simulator with
 * {@link SimSweepOptions}, and how they run: Ctrl-C or SIGTERM cancels the work (the runs in
 * progress stop at their next tick) and waits until the outputs are written; a sweep error is
 * one line and exit code 2, as a {@link org.parpe.cli.options.UsageException} is ({@link org.parpe.cli.Main#failed}).
 */
abstract class SimSweepCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE", descriptionKey = "file", description = "The PARSL script.")
    Path file;

    @Mixin
    SimSweepOptions options;

    @Spec
    CommandSpec spec;

    /** What Ctrl-C leaves, said after it: the hook holds the exit until the outputs are written. */
    abstract String kept();

    /** The command's work, given its output, its error stream and the cancellation flag. */
    abstract int execute(PrintWriter out, PrintWriter err, Cancellation cancel) throws Exception;

    @Override
    public final Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        Cancellation cancel = new Cancellation();
        try (InterruptHook hook = new InterruptHook(cancel::cancel, 5)) {
            int code = execute(spec.commandLine().getOut(), err, cancel);
            if (hook.interrupted()) {
                err.println("parpe: " + hook.cause() + ": " + kept());
            }
            return code;
        } catch (SweepException e) {
            err.println("parpe: " + e.getMessage());
            return 2;
        }
    }
}
