package org.parpe.gui.app;

import org.eclipse.swt.SWTException;
import org.parpe.gui.run.CrashLog;
import org.parpe.gui.text.UiMsg;

/**
 * A failure of PARPE itself while the window handled an event: a run going on is stopped first if
 * it is an Error (the window's state is unknown after one; Esc's stop, so that modules on the bus
 * stop at once and a run never goes on unwatched), then the crash file is written and named in the
 * Run log and the status bar. The same failure again (a listener failing on each paint) names the
 * file written for it the first time. UI thread only.
 */
final class EventFailures {
    private final IdeWindow ide;
    private String lastCrash;
    private String lastCrashFile;

    EventFailures(IdeWindow ide) {
        this.ide = ide;
    }

    /** Reports {@code e}; returns the crash file. */
    String report(Throwable e) {
        // asyncExec hands on a runnable's Error wrapped in an SWTException
        if (e instanceof Error || e instanceof SWTException s && s.throwable instanceof Error) {
            try {
                ide.runs.emergencyStop();
            } catch (RuntimeException | Error stopFailed) {
                e.addSuppressed(stopFailed);
            }
        }
        StackTraceElement[] at = e.getStackTrace();
        String what = e + (at.length > 0 ? " at " + at[0] : "");
        if (!what.equals(lastCrash)) {
            lastCrash = what;
            lastCrashFile = CrashLog.write("handling a UI event", e);
        }
        try {
            String message = UiMsg.INTERNAL_ERROR_UI.text(e, lastCrashFile);
            ide.bottom.log(message);
            ide.status.setMessage(message);
        } catch (RuntimeException | Error notShown) {
            // The file is written; the window cannot say so.
        }
        return lastCrashFile;
    }
}
