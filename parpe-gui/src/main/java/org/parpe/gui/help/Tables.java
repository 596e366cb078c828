package org.parpe.gui.help;

import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.graphics.GC;

/**
 * How the tutorial lays out a table in its text: in columns (tab stops, each column as wide as
 * its widest cell) where it fits the text's width, else as {@link TableCards cards} whose wrapped
 * cells hang under their own start.
 */
final class Tables {
    private Tables() {
    }

    /** Whether {@code table} (rows of cells separated by tabs) is wider in columns than {@code text}'s column. */
    static boolean tooWide(StyledText text, String table) {
        int room = text.getClientArea().width - text.getLeftMargin() - text.getRightMargin();
        return room > 0 && columnWidths(text, List.of(table.split("\n", -1))).stream().mapToInt(Integer::intValue).sum() > room;
    }

    /** Tab stops for a table's {@code lines} lines from {@code offset}: each column as wide as its widest cell. */
    static void tabStops(StyledText text, int offset, int lines) {
        int first = text.getLineAtOffset(offset);
        List<String> rows = new ArrayList<>();
        for (int l = first; l < first + lines; l++) {
            rows.add(text.getLine(l));
        }
        List<Integer> widths = columnWidths(text, rows);
        int[] stops = new int[Math.max(1, widths.size() - 1)];
        int x = 0;
        for (int c = 0; c < stops.length && c < widths.size(); c++) {
            x += widths.get(c);
            stops[c] = x;
        }
        text.setLineTabStops(first, lines, stops);
    }

    /** A card's cell that wraps goes on under its own start, not under the row's number ({@code lines} lines from {@code offset}). */
    static void hangCards(StyledText text, int offset, int lines) {
        int first = text.getLineAtOffset(offset);
        GC gc = new GC(text);
        int cell = gc.textExtent(TableCards.INDENT).x;
        gc.dispose();
        for (int l = first; l < first + lines; l++) {
            text.setLineWrapIndent(l, 1, text.getLine(l).startsWith(TableCards.INDENT) ? cell : cell / 2);
        }
    }

    /** The width of each column of a table's {@code lines} (cells separated by tabs): its widest cell and a gap. */
    private static List<Integer> columnWidths(StyledText text, List<String> lines) {
        GC gc = new GC(text);
        try {
            List<Integer> widths = new ArrayList<>();
            for (String line : lines) {
                String[] cells = line.split("\t", -1);
                for (int c = 0; c < cells.length; c++) {
                    int w = gc.textExtent(cells[c]).x + 24;
                    if (widths.size() <= c) {
                        widths.add(w);
                    } else {
                        widths.set(c, Math.max(widths.get(c), w));
                    }
                }
            }
            return widths;
        } finally {
            gc.dispose();
        }
    }
}
