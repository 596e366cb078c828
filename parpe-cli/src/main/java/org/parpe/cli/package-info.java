/** The parpe command line: check, run, the run loop and the extension points of run targets. */
package org.parpe.cli;
