package org.parpe.cli.options;

/**
 * A bad command-line value (unknown parameter, unreadable file, unusable port …): printed as
 * one line and ends the command with exit code 2.
 */
public final class UsageException extends Exception {
    /** An exception whose message is shown to the user as it is. */
    public UsageException(String message) {
        super(message, null, false, false);
    }
}
