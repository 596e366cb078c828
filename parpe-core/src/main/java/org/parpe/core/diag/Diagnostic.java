package org.parpe.core.diag;

/**
 * One problem found in a script, with its place.
 *
 * @param severity error or warning
 * @param pos      where the problem is
 * @param message  what was found and what was expected
 */
public record Diagnostic(Severity severity, SourcePos pos, String message) {

    /** {@code FILE:LINE:COL: error: MESSAGE}, the form of PARSL.md §1. */
    public String format() {
        return pos + ": " + severity.word() + ": " + message;
    }

    @Override
    public String toString() {
        return format();
    }
}
