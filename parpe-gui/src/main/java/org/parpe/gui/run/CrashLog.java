package org.parpe.gui.run;

import org.parpe.core.io.CrashReport;
import org.parpe.gui.prefs.Prefs;

/**
 * The IDE's crash files go under {@code ~/.parpe/crash/}, written by the one crash writer
 * ({@link CrashReport}) the command line uses too.
 */
public final class CrashLog {
    private CrashLog() {
    }

    /** Writes {@code e} with what was being done; returns the file's path (or a note if it failed). */
    public static String write(String doing, Throwable e) {
        return CrashReport.write(Prefs.defaultHome().resolve("crash"), doing, e);
    }
}
