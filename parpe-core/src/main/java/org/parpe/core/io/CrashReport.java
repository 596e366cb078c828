package org.parpe.core.io;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.parpe.core.Version;

/**
 * The one writer of crash files, for the command line and the IDE: a failure of PARPE itself
 * goes to a new file of its own, and the user is shown one line naming it, never a stack trace.
 */
public final class CrashReport {
    private CrashReport() {
    }

    /**
     * Writes {@code e}, with what PARPE was doing and on which Java, to a new file in {@code dir}
     * (created if missing); returns the file's path, or a note saying why none was written.
     */
    public static String write(Path dir, String doing, Throwable e) {
        StringWriter trace = new StringWriter();
        e.printStackTrace(new PrintWriter(trace));
        try {
            Files.createDirectories(dir);
            Path f = Files.createTempFile(dir, "parpe-crash-", ".txt"); // a new name of its own
            AtomicFiles.write(f, "PARPE " + Version.NUMBER + " internal error while " + doing + "\n"
                    + "java " + System.getProperty("java.version") + ", " + System.getProperty("os.name") + "\n\n"
                    + trace);
            return f.toString();
        } catch (IOException | RuntimeException io) {
            return "(could not write a crash file: " + io.getMessage() + ")";
        }
    }
}
