package org.parpe.core.diagram;

import org.parpe.core.diag.SourcePos;

/**
 * Something a diagram cannot draw, shown as its text with the place that opens the text there.
 *
 * @param text what is written, or what the view could not show
 * @param pos  where it is written
 */
public record TextIsland(String text, SourcePos pos) {
}
