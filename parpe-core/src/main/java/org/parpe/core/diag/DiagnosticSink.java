package org.parpe.core.diag;

/**
 * Where the stages of the pipeline write what they find. Generating a diagnostic is separate
 * from reporting it: the CLI prints, the IDE fills its Problems view, tests collect.
 */
@FunctionalInterface
public interface DiagnosticSink {

    /** Receives one diagnostic. */
    void report(Diagnostic diagnostic);

    /** Reports an error at {@code pos}. */
    default void error(SourcePos pos, String message) {
        report(new Diagnostic(Severity.ERROR, pos, message));
    }

    /** Reports a warning at {@code pos}. */
    default void warning(SourcePos pos, String message) {
        report(new Diagnostic(Severity.WARNING, pos, message));
    }
}
