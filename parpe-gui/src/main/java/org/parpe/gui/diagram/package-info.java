/**
 * The IDE's Diagram pane (issue 24): the open document drawn as the core's diagrams
 * ({@code org.parpe.core.diagram}) on an SWT canvas, linked with the text both ways through the
 * nodes' source spans, with edits written back through
 * {@link org.parpe.core.diagram.DiagramEdits} as one Undo step each.
 * {@link org.parpe.gui.diagram.Projection} makes a view from a text off the UI thread,
 * {@link org.parpe.gui.diagram.SceneCanvas} draws a {@code Scene} with SWT and
 * {@link org.parpe.gui.diagram.DiagramPane} is the widget.
 */
package org.parpe.gui.diagram;
