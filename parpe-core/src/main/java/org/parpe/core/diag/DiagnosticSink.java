package org.parpe.core.diag;

import org.parpe.core.text.Key;

/**
 * Where the stages of the pipeline write what they find. Generating a diagnostic is separate
 * from reporting it: the CLI prints, the IDE fills its Problems view, tests collect.
 */
@FunctionalInterface
public interface DiagnosticSink {

    /** Receives one diagnostic. */
    void report(Diagnostic diagnostic);

    /** Reports an error at {@code pos}: the text of {@code key} with {@code args}. */
    default void error(SourcePos pos, Key key, Object... args) {
        report(new Diagnostic(Severity.ERROR, pos, key, args));
    }

    /** Reports a warning at {@code pos}: the text of {@code key} with {@code args}. */
    default void warning(SourcePos pos, Key key, Object... args) {
        report(new Diagnostic(Severity.WARNING, pos, key, args));
    }

    /** Reports an error at {@code pos} with a text PARPE does not translate. */
    default void error(SourcePos pos, String message) {
        report(new Diagnostic(Severity.ERROR, pos, message));
    }

    /** Reports a warning at {@code pos} with a text PARPE does not translate. */
    default void warning(SourcePos pos, String message) {
        report(new Diagnostic(Severity.WARNING, pos, message));
    }
}
