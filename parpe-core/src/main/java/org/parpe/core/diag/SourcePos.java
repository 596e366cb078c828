package org.parpe.core.diag;

/**
 * A place in a source file: 1-based line and column. Every model node and every diagnostic
 * carries one so that messages can be printed as {@code FILE:LINE:COL}. The place of an
 * element read from a file also carries the element's {@link SourceSpan}, so that an editor
 * can rewrite one attribute of the node exactly, and its character offset, so that the editor
 * and the grid put a diagnostic on its characters without turning line and column into an
 * offset again; span and offset are extra knowledge about the same place and take no part in
 * equality.
 *
 * @param file   the file as the user named it (relative paths stay relative)
 * @param line   1-based line
 * @param column 1-based column
 * @param span   the element's offsets in its file's text, or {@code null} when unknown
 * @param offset the place's character offset in its file's text (for a place past the end of
 *               its line, the line's end), or -1 when unknown
 */
public record SourcePos(String file, int line, int column, SourceSpan span, int offset) {

    /** A place without a span or an offset. */
    public SourcePos(String file, int line, int column) {
        this(file, line, column, null, -1);
    }

    /** A position for things that come from no file (command line, generated code). */
    public static final SourcePos NONE = new SourcePos("", 0, 0);

    /**
     * A place that is not in a file but names where a problem comes from: a device
     * ({@code bus /dev/ttyUSB0}), a command-line option ({@code --param}), the simulator. It
     * prints as its name alone.
     */
    public static SourcePos origin(String name) {
        return new SourcePos(name, 0, 0);
    }

    /** The position {@code delta} columns to the right on the same line. */
    public SourcePos shift(int delta) {
        return new SourcePos(file, line, column + delta, null, offset < 0 ? -1 : offset + delta);
    }

    /** This place with the element's span. */
    public SourcePos withSpan(SourceSpan s) {
        return new SourcePos(file, line, column, s, offset);
    }

    /** Equal when file, line and column are: the span does not make another place. */
    @Override
    public boolean equals(Object o) {
        return o instanceof SourcePos p && p.line == line && p.column == column && p.file.equals(file);
    }

    @Override
    public int hashCode() {
        return (file.hashCode() * 31 + line) * 31 + column;
    }

    @Override
    public String toString() {
        if (line == 0) {
            return file.isEmpty() ? "<no place>" : file;
        }
        return file + ":" + line + ":" + column;
    }
}
