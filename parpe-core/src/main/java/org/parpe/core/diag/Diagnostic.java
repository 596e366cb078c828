package org.parpe.core.diag;

/**
 * One problem found in a script, with its place.
 *
 * @param severity error or warning
 * @param pos      where the problem is: file, line and column, and for a problem in a file's text
 *                 the offset of its characters ({@link SourcePos#offset()}), which the editor
 *                 and the grid mark
 * @param message  what was found and what was expected
 */
public record Diagnostic(Severity severity, SourcePos pos, String message) {

    /** {@code FILE:LINE:COL: error: MESSAGE}, the form of PARSL.md §1. */
    public String format() {
        return format(1);
    }

    /**
     * The message of {@code repeats} equal diagnostics shown as one, as the IDE's Problems view
     * and the command line fold them: {@code MESSAGE  (×3)}; the message alone for one.
     */
    public String message(int repeats) {
        return repeats > 1 ? message + "  (\u00d7" + repeats + ")" : message;
    }

    /** {@link #format()} of {@code repeats} equal diagnostics shown as one ({@link #message(int)}). */
    public String format(int repeats) {
        return pos + ": " + severity.word() + ": " + message(repeats);
    }

    @Override
    public String toString() {
        return format();
    }
}
