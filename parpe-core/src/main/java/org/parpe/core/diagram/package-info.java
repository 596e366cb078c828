/**
 * Diagrams of a loaded program (public API): the {@code <main>} program lane, behavior
 * swimlanes, the automaton ring, the phase wheel and the gait diagram as plain records that a
 * view draws, and {@link org.parpe.core.diagram.DiagramEdits}, which turns an edit made on a
 * diagram into one exact replacement in the script's text through the nodes' source spans.
 * What a view cannot draw is kept as a {@link org.parpe.core.diagram.TextIsland} with its
 * place. No UI or I/O library: the CLI and the IDE draw these records.
 */
package org.parpe.core.diagram;
