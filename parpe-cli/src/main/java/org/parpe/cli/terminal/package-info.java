/**
 * What the commands write on the terminal and how they end: the load report, folded run
 * diagnostics, the progress line rewritten in place, Ctrl-C and SIGTERM, and the exit codes
 * more than one command returns.
 */
package org.parpe.cli.terminal;
