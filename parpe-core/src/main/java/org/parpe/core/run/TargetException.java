package org.parpe.core.run;

import java.util.List;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;

/**
 * A run target that cannot be used because of the user's input or the environment (a robot
 * configuration with errors, a serial port that does not open, no module answering). Not a
 * failure of PARPE: the command line reports it as a usage error (exit 2), the IDE in its
 * Problems view. The diagnostics say what is wrong and where.
 */
public final class TargetException extends Exception {
    private static final long serialVersionUID = 1L;
    private final transient List<Diagnostic> diagnostics;

    /** A failure described by {@code diagnostics} (at least one error), summarised by {@code message}. */
    public TargetException(String message, List<Diagnostic> diagnostics) {
        super(message, null, false, false);
        this.diagnostics = List.copyOf(diagnostics);
    }

    /** A failure with one error at {@code where}. */
    public TargetException(SourcePos where, String message) {
        this(where + ": " + message, List.of(new Diagnostic(Severity.ERROR, where, message)));
    }

    /** A failure with one error at {@code where}: the text of {@code key} with {@code args}. */
    public TargetException(SourcePos where, org.parpe.core.text.Key key, Object... args) {
        this(new Diagnostic(Severity.ERROR, where, key, args));
    }

    private TargetException(Diagnostic d) {
        this(d.pos() + ": " + d.message(), List.of(d));
    }

    /** What is wrong, with places. */
    public List<Diagnostic> diagnostics() {
        return diagnostics;
    }
}
