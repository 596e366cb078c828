package org.parpe.cli.terminal;

/**
 * The exit code that more than one command returns by name (the others are the literals of
 * {@code parpe --help}'s footer: 0 success, 1 script errors, 2 usage errors, 3 run-time error).
 */
public final class ExitCode {
    /** A failure of PARPE itself, distinct from a script's run-time error (3). */
    public static final int INTERNAL_ERROR = 4;

    private ExitCode() {
    }
}
