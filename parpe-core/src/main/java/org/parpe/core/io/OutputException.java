package org.parpe.core.io;

/** An output that may not or could not be written; the message names the option and the file. */
public final class OutputException extends Exception {
    private static final long serialVersionUID = 1L;

    /** An output refused or failed, with the whole message. */
    public OutputException(String message) {
        super(message);
    }
}
