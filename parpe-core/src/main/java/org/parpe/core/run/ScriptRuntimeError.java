package org.parpe.core.run;

import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/**
 * A run-time error of the script (a non-finite value, a period ≤ 0, …). Its message is the
 * located diagnostic {@code FILE:LINE:COL: error: …}; the run stops with exit code 3 and the
 * modules hold their last finite angles.
 */
public final class ScriptRuntimeError extends RuntimeException {
    private final SourcePos pos;
    private final double time;
    private final transient Message detail;

    /** An error at {@code pos} during the tick at {@code time}. */
    public ScriptRuntimeError(SourcePos pos, Message message, double time) {
        super(null, null, false, false);
        this.pos = pos;
        this.time = time;
        this.detail = Message.of(Msg.AT_TIME, message, String.format(java.util.Locale.ROOT, "%.6f", time));
    }

    /** The located diagnostic {@code FILE:LINE:COL: error: …}, in the chosen language. */
    @Override
    public String getMessage() {
        return diagnostic().format();
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
