package org.parpe.cli.sweep;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.parpe.sim.sweep.SweepListener;
import org.parpe.sim.sweep.SweepRow;

/**
 * A progress bar on a terminal's standard error ({@code [#####.....] 120/500 runs, 9.8 runs/s,
 * 0:39 left}), redrawn at most five times a second and cleared at the end; silent when standard
 * error is not a terminal. Rows are passed on to another listener.
 */
final class ProgressBar implements SweepListener {
    private static final int WIDTH = 30;

    private final PrintWriter err;
    private final SweepListener next;
    private final boolean enabled;
    private final long start = System.nanoTime();
    private long last;
    private boolean shown;

    ProgressBar(PrintWriter err, SweepListener next) {
        this.err = err;
        this.next = next;
        this.enabled = stderrIsTerminal();
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
    public void row(SweepRow row) {
        next.row(row);
    }

    @Override
    public void progress(int done, int total) {
        next.progress(done, total);
        long now = System.nanoTime();
        if (!enabled || (now - last < 200_000_000L && done < total)) {
            return;
        }
        last = now;
        shown = true;
        double seconds = (now - start) / 1e9;
        double rate = done / Math.max(seconds, 1e-9);
        int filled = total == 0 ? WIDTH : (int) ((long) WIDTH * done / total);
        long left = Math.round((total - done) / Math.max(rate, 1e-9));
        err.print(String.format(Locale.ROOT, "\r[%s%s] %d/%d runs, %.1f runs/s, %d:%02d left   ", "#".repeat(filled),
                ".".repeat(WIDTH - filled), done, total, rate, left / 60, left % 60));
        err.flush();
    }

    /** Clears the bar. */
    void clear() {
        if (shown) {
            err.print("\r" + " ".repeat(WIDTH + 60) + "\r");
            err.flush();
        }
    }
}
