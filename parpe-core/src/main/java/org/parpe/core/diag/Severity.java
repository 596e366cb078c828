package org.parpe.core.diag;

/** How bad a diagnostic is: errors stop a script from running, warnings do not. */
public enum Severity {
    ERROR, WARNING;

    /** The word used in printed diagnostics ({@code error}, {@code warning}). */
    public String word() {
        return this == ERROR ? "error" : "warning";
    }
}
