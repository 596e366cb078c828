package org.parpe.gui.grid;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.eclipse.jface.text.BadLocationException;
import org.eclipse.jface.text.IDocument;
import org.parpe.core.diag.Diagnostic;

/**
 * The script's diagnostics placed on the grid: each one whose line and column fall on an entry
 * (or a {@code times} entry) marks that cell with its own message; others that name the table
 * are listed under the grid.
 */
final class CellProblems {
    private CellProblems() {
    }

    /**
     * Puts each of {@code diagnostics} on its cell in {@code problems} (keyed by
     * {@link GridView#cellKey}, grid column 0 being the times), or in {@code others} if it is
     * elsewhere but names the table.
     */
    static void place(IDocument doc, GaitTable table, List<Diagnostic> diagnostics, Map<Long, String> problems,
                      List<String> others) {
        for (Diagnostic d : diagnostics) {
            // the offset the loader recorded; a place without one (not in a script's text) by line and column
            int offset = d.pos().offset() >= 0 ? d.pos().offset() : offset(doc, d.pos().line(), d.pos().column());
            long cell = offset < 0 ? -1 : cellAt(table, offset);
            if (cell >= 0) {
                problems.merge(cell, d.message(), (a, b) -> a + "\n" + b);
            } else if (d.message().contains("'" + table.name() + "'")) {
                others.add(d.severity().name().toLowerCase(Locale.ROOT) + ": " + d.message());
            }
        }
    }

    private static long cellAt(GaitTable table, int offset) {
        for (int r = 0; r < table.rows().size(); r++) {
            List<Cell> row = table.rows().get(r);
            for (int c = 0; c < row.size(); c++) {
                if (row.get(c).covers(offset)) {
                    return GridView.cellKey(r, c + 1);
                }
            }
            if (table.times() != null && r < table.times().size() && table.times().get(r).covers(offset)) {
                return GridView.cellKey(r, 0);
            }
        }
        return -1;
    }

    private static int offset(IDocument doc, int line, int column) {
        try {
            return line < 1 || line > doc.getNumberOfLines() ? -1 : doc.getLineOffset(line - 1) + column - 1;
        } catch (BadLocationException e) {
            return -1;
        }
    }
}
