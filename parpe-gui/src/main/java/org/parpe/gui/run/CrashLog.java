package org.parpe.gui.run;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import org.parpe.core.io.AtomicFiles;
import org.parpe.gui.prefs.Prefs;

/**
 * Writes internal failures to a file under {@code ~/.parpe/crash/} so that the user sees one
 * line naming the file to attach to a bug report, never a stack trace.
 */
public final class CrashLog {
    private CrashLog() {
    }

    /** Writes {@code e} with what was being done; returns the file's path (or a note if it failed). */
    public static String write(String doing, Throwable e) {
        StringWriter sw = new StringWriter();
        e.printStackTrace(new PrintWriter(sw));
        try {
            Path dir = Prefs.defaultHome().resolve("crash");
            Files.createDirectories(dir);
            Path f = dir.resolve("parpe-" + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss-SSS")) + ".txt");
            AtomicFiles.write(f, "PARPE IDE internal error while " + doing + "\n"
                    + "java " + System.getProperty("java.version") + ", " + System.getProperty("os.name") + "\n\n" + sw);
            return f.toString();
        } catch (IOException io) {
            return "(could not write a crash file: " + io.getMessage() + ")";
        }
    }
}
