package org.parpe.core.diag;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** A sink that keeps every diagnostic in the order reported. */
public final class DiagnosticList implements DiagnosticSink {
    private final List<Diagnostic> items = new ArrayList<>();

    @Override
    public synchronized void report(Diagnostic diagnostic) {
        items.add(diagnostic);
    }

    /** The diagnostics so far, oldest first. */
    public synchronized List<Diagnostic> all() {
        return Collections.unmodifiableList(new ArrayList<>(items));
    }

    /** Whether any error (not warning) was reported. */
    public synchronized boolean hasErrors() {
        return items.stream().anyMatch(d -> d.severity() == Severity.ERROR);
    }

    /** Number of errors reported. */
    public synchronized long errorCount() {
        return items.stream().filter(d -> d.severity() == Severity.ERROR).count();
    }
}
