package org.parpe.cli.sweep;

import org.parpe.cli.text.CliMsg;
import java.io.PrintWriter;
import java.util.Locale;
import org.parpe.cli.terminal.TerminalLine;
import org.parpe.sim.sweep.SweepListener;
import org.parpe.sim.sweep.SweepRow;

/**
 * A progress bar on a terminal's standard error ({@code [#####.....] 120/500 runs, 9.8 runs/s,
 * 0:39 left}), redrawn at most five times a second and cleared at the end; silent when standard
 * error is not a terminal. There (a batch job's log, a pipe) it writes whole lines instead:
 * one at every tenth of the runs and at least one a minute while runs finish. Rows are passed on
 * to another listener.
 */
final class ProgressBar implements SweepListener {
    private static final int WIDTH = 30;

    private final TerminalLine line;
    private final SweepListener next;
    private static final long LOG_GAP_NANOS = 60_000_000_000L;

    private final PrintWriter err;
    private final long start = System.nanoTime();
    private long logged = start;
    private int loggedTenth;

    ProgressBar(PrintWriter err, SweepListener next) {
        this.err = err;
        this.line = TerminalLine.onStderr(err);
        this.next = next;
    }

    @Override
    public void row(SweepRow row) {
        next.row(row);
    }

    @Override
    public void progress(int done, int total) {
        next.progress(done, total);
        long now = System.nanoTime();
        if (!line.terminal()) {
            log(done, total, now);
            return;
        }
        if (!line.due(now, done >= total)) {
            return;
        }
        int filled = total == 0 ? WIDTH : (int) ((long) WIDTH * done / total);
        line.show(String.format(Locale.ROOT, "[%s%s] %s", "#".repeat(filled), ".".repeat(WIDTH - filled),
                status(done, total, now)));
    }

    /** A whole line for a log, at every tenth of the runs and at least once a minute. */
    private void log(int done, int total, long now) {
        int tenth = total == 0 ? 10 : (int) (10L * done / total);
        if (tenth == loggedTenth && now - logged < LOG_GAP_NANOS) {
            return;
        }
        loggedTenth = tenth;
        logged = now;
        err.println("parpe: " + status(done, total, now));
        err.flush();
    }

    private String status(int done, int total, long now) {
        double rate = done / Math.max((now - start) / 1e9, 1e-9);
        long left = Math.round((total - done) / Math.max(rate, 1e-9));
        return CliMsg.SWEEP_PROGRESS.text(done, total, String.format(Locale.ROOT, "%.1f", rate),
                String.format(Locale.ROOT, "%d:%02d", left / 60, left % 60));
    }

    /** Clears the bar. */
    void clear() {
        line.clear();
    }
}
