/**
 * The gait-table grid editor (PARSL Level II): a gait table of the script shown as a grid of
 * rows (time steps) by modules, kept in step with the text. {@link org.parpe.gui.grid.TableText}
 * finds the tables and their cells in the text with the core's XML reader (which gives every
 * character's place), {@link org.parpe.gui.grid.TableEdits} turns grid edits into a new text
 * for the table's range only, and {@link org.parpe.gui.grid.GridPane} is the widget.
 */
package org.parpe.gui.grid;
