package org.parpe.core.diag;

import org.parpe.core.text.Key;
import org.parpe.core.text.Message;

/**
 * One problem found in a script, with its place.
 *
 * @param severity error or warning
 * @param pos      where the problem is: file, line and column, and for a problem in a file's text
 *                 the offset of its characters ({@link SourcePos#offset()}), which the editor
 *                 and the grid mark
 * @param text     what was found and what was expected: a bundle key and its arguments, shown
 *                 in the chosen language ({@link org.parpe.core.text.Lang}); the place and the
 *                 words {@code error}/{@code warning} stay as they are in every language, for
 *                 the tools that read them
 */
public record Diagnostic(Severity severity, SourcePos pos, Message text) {

    /** A diagnostic whose text is {@code key} with {@code args}. */
    public Diagnostic(Severity severity, SourcePos pos, Key key, Object... args) {
        this(severity, pos, Message.of(key, args));
    }

    /**
     * A diagnostic with a text PARPE does not translate ({@link Message#verbatim}): a library's
     * or the operating system's words, or a part of PARPE not yet in the bundles.
     */
    public Diagnostic(Severity severity, SourcePos pos, String message) {
        this(severity, pos, Message.verbatim(message));
    }

    /** What was found and what was expected, in the chosen language. */
    public String message() {
        return text.toString();
    }

    /** {@code FILE:LINE:COL: error: MESSAGE}, the form of PARSL.md §1. */
    public String format() {
        return format(1);
    }

    /**
     * The message of {@code repeats} equal diagnostics shown as one, as the IDE's Problems view
     * and the command line fold them: {@code MESSAGE  (×3)}; the message alone for one.
     */
    public String message(int repeats) {
        return repeats > 1 ? message() + "  (\u00d7" + repeats + ")" : message();
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
