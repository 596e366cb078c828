/**
 * The PNG pictures of the command line: the plots of {@code --plot}, the sweep, optimisation
 * and merge ({@link org.parpe.cli.plot.PngCharts}, drawn with XChart) and the canvas diagrams
 * are drawn on ({@link org.parpe.cli.plot.Canvas}).
 */
package org.parpe.cli.plot;
