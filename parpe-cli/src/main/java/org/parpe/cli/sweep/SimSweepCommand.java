package org.parpe.cli.sweep;

import java.io.PrintWriter;
import org.parpe.cli.InterruptHook;
import org.parpe.cli.UsageException;
import org.parpe.sim.sweep.Cancellation;
import org.parpe.sim.sweep.SweepException;
import picocli.CommandLine.Model.CommandSpec;

/**
 * How {@code sweep} and {@code optimize} run: Ctrl-C or SIGTERM cancels the work (the runs in progress stop
 * at their next tick) and waits until the outputs are written; usage and sweep errors are one
 * line and exit code 2.
 */
final class Interruptible {
    /** The command's work, given its output, its error stream and the cancellation flag. */
    interface Work {
        int execute(PrintWriter out, PrintWriter err, Cancellation cancel) throws Exception;
    }

    private Interruptible() {
    }

    /** Runs {@code work}; after Ctrl-C says that it {@code kept} what was done. */
    static int call(CommandSpec spec, String kept, Work work) throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        Cancellation cancel = new Cancellation();
        try (InterruptHook hook = new InterruptHook(cancel::cancel, 5)) {
            int code = work.execute(spec.commandLine().getOut(), err, cancel);
            if (hook.interrupted()) {
                err.println("parpe: " + hook.cause() + ": " + kept);
            }
            return code;
        } catch (UsageException | SweepException e) {
            err.println("parpe: " + e.getMessage());
            return 2;
        }
    }
}
