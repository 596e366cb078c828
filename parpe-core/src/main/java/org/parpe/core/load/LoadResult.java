package org.parpe.core.load;

import java.nio.file.Path;
import java.util.List;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.model.Program;

/**
 * What loading a script gave.
 *
 * @param program         the validated model, or {@code null} when there were errors
 * @param diagnostics     every error and warning found, in the order found
 * @param parameterErrors problems with parameter values given from outside (command line,
 *                        parameters dialog): unknown names (at {@code --param NAME}) or values
 *                        out of range (at the parameter's definition)
 * @param files           every file that was read: the script, its includes and its robot file
 */
public record LoadResult(Program program, List<Diagnostic> diagnostics, List<Diagnostic> parameterErrors,
                         List<Path> files) {

    public LoadResult {
        diagnostics = List.copyOf(diagnostics);
        parameterErrors = List.copyOf(parameterErrors);
        files = List.copyOf(files);
    }

    /** A result that read no file (for example a buffer that could not be loaded). */
    public LoadResult(Program program, List<Diagnostic> diagnostics, List<Diagnostic> parameterErrors) {
        this(program, diagnostics, parameterErrors, List.of());
    }

    /** Whether the script loaded without errors and every given parameter value was accepted. */
    public boolean ok() {
        return program != null && parameterErrors.isEmpty();
    }

    /** Only the errors. */
    public List<Diagnostic> errors() {
        return diagnostics.stream().filter(d -> d.severity() == Severity.ERROR).toList();
    }
}
