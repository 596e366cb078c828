/**
 * The IDE's Sweep/Optimise dialog (Run → Sweep / Optimise…): runs the engine of
 * {@link org.parpe.sim.sweep} on the editor's script on worker threads, shows progress, a
 * sortable results table and a plot drawn with SWT, applies the best values to the script's
 * parameter defaults as one undoable edit, and saves the rows as CSV.
 */
package org.parpe.gui.sweep;
