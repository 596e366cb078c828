package org.parpe.cli.terminal;

import java.util.function.Consumer;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.LoadResult;

/** What the commands that load a script (run, export, diagram) print of the load and how they end. */
public final class LoadReport {
    private LoadReport() {
    }

    /**
     * Prints every diagnostic of {@code r} to {@code err}; returns 0 when the program can be
     * used, 1 after script errors, 2 after bad {@code --param} values (printed too).
     */
    public static int exitCode(LoadResult r, Consumer<String> err) {
        for (Diagnostic d : r.diagnostics()) {
            err.accept(d.format());
        }
        if (r.program() == null) {
            return 1;
        }
        if (!r.parameterErrors().isEmpty()) {
            r.parameterErrors().forEach(d -> err.accept(d.format()));
            return 2;
        }
        return 0;
    }
}
