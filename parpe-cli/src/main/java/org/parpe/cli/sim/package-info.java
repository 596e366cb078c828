/** The simulator on the command line: --sim, --metrics, --plot, --realtime, and parpe race. */
package org.parpe.cli.sim;
