package org.parpe.core.run;

import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;

/**
 * A run-time error of the script (a non-finite value, a period ≤ 0, …). Its message is the
 * located diagnostic {@code FILE:LINE:COL: error: …}; the run stops with exit code 3 and the
 * modules hold their last finite angles.
 */
public final class ScriptRuntimeError extends RuntimeException {
    private final SourcePos pos;
    private final double time;
    private final String detail;

    /** An error at {@code pos} during the tick at {@code time}. */
    public ScriptRuntimeError(SourcePos pos, String message, double time) {
        super(new Diagnostic(Severity.ERROR, pos, detail(message, time)).format(), null, false, false);
        this.pos = pos;
        this.time = time;
        this.detail = detail(message, time);
    }

    private static String detail(String message, double time) {
        return message + String.format(java.util.Locale.ROOT, " (at t=%.6f s)", time);
    }

    /** The error as a located diagnostic (its {@code format()} is this exception's message). */
    public Diagnostic diagnostic() {
        return new Diagnostic(Severity.ERROR, pos, detail);
    }

    /** Where the failing expression or instance is. */
    public SourcePos pos() {
        return pos;
    }

    /** The time of the failing tick. */
    public double time() {
        return time;
    }
}
