package org.parpe.cli.terminal;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Consumer;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticSink;

/**
 * A run's diagnostics on the command line, folded as the IDE's Problems view folds them: the
 * first of equal ones is printed when it comes, its repeats are counted, and when the run ends
 * each that came more than once is printed again with its count ({@link Diagnostic#format(int)},
 * {@code … (×3)}). A bus warning said again and again (a servo stopping on its watchdog at every
 * stall of the host) is then two lines, not one per stop. Any thread: the bus reports from its own.
 */
public final class FoldedDiagnostics implements DiagnosticSink {
    private final Consumer<String> out;
    private final Map<Diagnostic, int[]> seen = new LinkedHashMap<>();

    /** Folds the diagnostics printed to {@code out}. */
    public FoldedDiagnostics(Consumer<String> out) {
        this.out = out;
    }

    @Override
    public synchronized void report(Diagnostic d) {
        if (seen.computeIfAbsent(d, k -> new int[1])[0]++ == 0) {
            out.accept(d.format());
        }
    }

    /** The end of the run: each diagnostic that came more than once, with its count. */
    public synchronized void finish() {
        for (Map.Entry<Diagnostic, int[]> e : seen.entrySet()) {
            if (e.getValue()[0] > 1) {
                out.accept(e.getKey().format(e.getValue()[0]));
            }
        }
        seen.clear();
    }
}
