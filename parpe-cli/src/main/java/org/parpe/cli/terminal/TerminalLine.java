package org.parpe.cli.terminal;

import java.io.Flushable;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * One line of standard error that is rewritten in place while long work goes on (a run's time, a
 * sweep's progress bar): redrawn at most five times a second, cleared at the end, and silent when
 * standard error is not a terminal, so that logs and pipes get no carriage returns.
 */
public final class TerminalLine {
    private static final long MIN_GAP_NANOS = 200_000_000L;

    private final Appendable out;
    private final Flushable flush;
    private final boolean enabled;
    private long last;
    private int width;

    private TerminalLine(Appendable out, Flushable flush, boolean enabled) {
        this.out = out;
        this.flush = flush;
        this.enabled = enabled;
    }

    /** A line on {@code err}, which is the process's standard error. */
    public static <T extends Appendable & Flushable> TerminalLine onStderr(T err) {
        return new TerminalLine(err, err, stderrIsTerminal());
    }

    private static boolean stderrIsTerminal() {
        try {
            String target = Files.readSymbolicLink(Path.of("/proc/self/fd/2")).toString();
            return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty");
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return false;
        }
    }

    /** Whether standard error is a terminal (else {@link #due} is never true). */
    public boolean terminal() {
        return enabled;
    }

    /** Whether a redraw at {@code now} (System.nanoTime) is due; {@code force} skips the rate limit. */
    public boolean due(long now, boolean force) {
        if (!enabled || !force && now - last < MIN_GAP_NANOS) {
            return false;
        }
        last = now;
        return true;
    }

    /** Rewrites the line with {@code text}. */
    public void show(String text) {
        width = Math.max(width, text.length() + 3);
        write("\r" + text + "   ");
    }

    /** Clears the line if anything was shown. */
    public void clear() {
        if (width > 0) {
            write("\r" + " ".repeat(width) + "\r");
            width = 0;
        }
    }

    private void write(String s) {
        try {
            out.append(s);
            flush.flush();
        } catch (IOException e) {
            // standard error is gone: nothing to show progress on
        }
    }
}
