package org.parpe.core.diag;

/**
 * A place in a source file: 1-based line and column. Every model node and every diagnostic
 * carries one so that messages can be printed as {@code FILE:LINE:COL}.
 *
 * @param file   the file as the user named it (relative paths stay relative)
 * @param line   1-based line
 * @param column 1-based column
 */
public record SourcePos(String file, int line, int column) {

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
        return new SourcePos(file, line, column + delta);
    }

    @Override
    public String toString() {
        if (line == 0) {
            return file.isEmpty() ? "<no place>" : file;
        }
        return file + ":" + line + ":" + column;
    }
}
