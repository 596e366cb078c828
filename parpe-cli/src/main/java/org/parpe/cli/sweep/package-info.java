/**
 * The sweep commands of the command line: {@code parpe sweep}, {@code parpe optimize} and
 * {@code parpe merge}, their PNG plots and their terminal progress bar, on top of the engine in
 * {@link org.parpe.sim.sweep}.
 */
package org.parpe.cli.sweep;
