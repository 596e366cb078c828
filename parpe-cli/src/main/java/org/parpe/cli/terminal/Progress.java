package org.parpe.cli.terminal;

import java.io.PrintStream;
import java.util.Locale;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.RunOutcome;

/**
 * A one-line progress report on a terminal's standard error for long runs: an observer of the
 * run that rewrites its line at most five times a second, from one second on, and clears it
 * at the end. Silent when standard error is not a terminal.
 */
public final class Progress implements JointSink {
    private final TerminalLine line;
    private final double limit;
    private long start;

    private Progress(TerminalLine line, double limit) {
        this.line = line;
        this.limit = limit;
    }

    /** Progress of a run of at most {@code limit} s ({@code +∞}: unknown) on {@code err}. */
    public static Progress forStderr(PrintStream err, double limit) {
        return new Progress(TerminalLine.onStderr(err), limit);
    }

    @Override
    public void start(org.parpe.core.run.RunInfo info) {
        start = System.nanoTime();
    }

    @Override
    public void accept(long tick, double t, double[] commanded) {
        long now = System.nanoTime();
        if (now - start < 1_000_000_000L || !line.due(now, false)) {
            return;
        }
        String of = Double.isInfinite(limit) ? "" : String.format(Locale.ROOT, " / %.1f s (%.0f%%)", limit, 100 * t / limit);
        line.show(org.parpe.cli.text.CliMsg.PROGRESS.text(String.format(Locale.ROOT, "%.1f", t), of,
                String.format(Locale.ROOT, "%.1f", t / ((now - start) / 1e9))));
    }

    @Override
    public void finish(RunOutcome outcome) {
        line.clear();
    }
}
