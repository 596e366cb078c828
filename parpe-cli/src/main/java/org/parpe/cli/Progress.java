package org.parpe.cli;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.RunOutcome;

/**
 * A one-line progress report on a terminal's standard error for long runs: an observer of the
 * run that rewrites its line at most five times a second, from one second on, and clears it
 * at the end. Silent when standard error is not a terminal.
 */
final class Progress implements JointSink {
    private final PrintStream err;
    private final double limit;
    private final boolean enabled;
    private long start;
    private long last;
    private boolean shown;

    private Progress(PrintStream err, double limit, boolean enabled) {
        this.err = err;
        this.limit = limit;
        this.enabled = enabled;
    }

    /** Progress of a run of at most {@code limit} s ({@code +∞}: unknown) on {@code err}. */
    static Progress forStderr(PrintStream err, double limit) {
        return new Progress(err, limit, stderrIsTerminal());
    }

    private static boolean stderrIsTerminal() {
        try {
            String target = Files.readSymbolicLink(Path.of("/proc/self/fd/2")).toString();
            return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty");
        } catch (Exception e) {
            return false;
        }
    }

    @Override
    public void start(org.parpe.core.run.RunInfo info) {
        start = System.nanoTime();
    }

    @Override
    public void accept(long tick, double t, double[] commanded) {
        if (!enabled) {
            return;
        }
        long now = System.nanoTime();
        if (now - start < 1_000_000_000L || now - last < 200_000_000L) {
            return;
        }
        last = now;
        shown = true;
        String of = Double.isInfinite(limit) ? "" : String.format(Locale.ROOT, " / %.1f s (%.0f%%)", limit, 100 * t / limit);
        err.print(String.format(Locale.ROOT, "\rparpe: t = %.1f s%s, %.1fx real time   ", t, of,
                t / ((now - start) / 1e9)));
        err.flush();
    }

    @Override
    public void finish(RunOutcome outcome) {
        if (shown) {
            err.print("\r" + " ".repeat(60) + "\r");
            err.flush();
        }
    }
}
