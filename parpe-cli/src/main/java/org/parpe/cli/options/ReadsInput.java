package org.parpe.cli.options;

import java.io.InputStream;

/**
 * A command that reads standard input (the emulator's console, the recorder's Enter key, the
 * calibration's answers). The command line hands it the input it was started with, so a command
 * run in-process (by the tests, by the IDE) never reads the process's own standard input, which
 * may belong to someone else (Surefire's forked JVM takes its orders there).
 */
public interface ReadsInput {
    /** Sets where the command reads its input lines from. */
    void readFrom(InputStream in);
}
