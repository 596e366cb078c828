package org.parpe.cli.sweep;

import java.io.PrintWriter;
import java.util.Locale;
import org.parpe.cli.TerminalLine;
import org.parpe.sim.sweep.SweepListener;
import org.parpe.sim.sweep.SweepRow;

/**
 * A progress bar on a terminal's standard error ({@code [#####.....] 120/500 runs, 9.8 runs/s,
 * 0:39 left}), redrawn at most five times a second and cleared at the end; silent when standard
 * error is not a terminal. Rows are passed on to another listener.
 */
final class ProgressBar implements SweepListener {
    private static final int WIDTH = 30;

    private final TerminalLine line;
    private final SweepListener next;
    private final long start = System.nanoTime();

    ProgressBar(PrintWriter err, SweepListener next) {
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
        if (!line.due(now, done >= total)) {
            return;
        }
        double seconds = (now - start) / 1e9;
        double rate = done / Math.max(seconds, 1e-9);
        int filled = total == 0 ? WIDTH : (int) ((long) WIDTH * done / total);
        long left = Math.round((total - done) / Math.max(rate, 1e-9));
        line.show(String.format(Locale.ROOT, "[%s%s] %d/%d runs, %.1f runs/s, %d:%02d left", "#".repeat(filled),
                ".".repeat(WIDTH - filled), done, total, rate, left / 60, left % 60));
    }

    /** Clears the bar. */
    void clear() {
        line.clear();
    }
}
