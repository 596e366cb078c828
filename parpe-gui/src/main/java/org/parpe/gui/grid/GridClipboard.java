package org.parpe.gui.grid;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.eclipse.swt.dnd.Clipboard;
import org.eclipse.swt.dnd.TextTransfer;
import org.eclipse.swt.dnd.Transfer;
import org.parpe.gui.grid.Fill.Selection;
import org.parpe.gui.grid.TableEdits.At;

/**
 * The grid editor's cells to and from the clipboard, as a spreadsheet has them: the selection
 * copied as tab-separated lines, and lines (tab- or comma-separated) pasted at the selection as
 * one edit of the table ({@link GridPane#writeCells}). UI thread only.
 */
final class GridClipboard {
    private final GridPane pane;
    private final GridView grid;

    GridClipboard(GridPane pane, GridView grid) {
        this.pane = pane;
        this.grid = grid;
    }

    /** Pastes {@code clip} (tab- or comma-separated lines) at the selection; returns how many cells fell outside. */
    int paste(String clip) {
        GaitTable table = pane.table();
        if (!pane.editable() || clip == null || clip.isBlank()) {
            return 0;
        }
        int[] outside = {0};
        Map<At, String> cells = new LinkedHashMap<>();
        Fill.paste(clip, grid.selection(), table.rows().size(), Math.max(1, table.width()) + 1, outside)
                .forEach((at, v) -> cells.put(GridPane.at(at.row(), at.column()), v));
        pane.writeCells(cells, outside[0]);
        return outside[0];
    }

    /** Pastes the clipboard's text at the selection. */
    void paste() {
        Clipboard cb = new Clipboard(grid.control().getDisplay());
        try {
            paste((String) cb.getContents(TextTransfer.getInstance()));
        } finally {
            cb.dispose();
        }
    }

    /** The selected cells as tab-separated lines, as a spreadsheet takes them. */
    String copyText() {
        GaitTable table = pane.table();
        Selection s = grid.selection();
        StringBuilder out = new StringBuilder();
        List<String> times = table.timeTexts();
        for (int r = s.r0(); r <= s.r1(); r++) {
            for (int c = s.c0(); c <= s.c1(); c++) {
                Cell cell = c == 0 ? null : table.cell(r, c - 1);
                String v = c == 0 ? (times == null ? "1" : r < times.size() ? times.get(r) : "") : cell == null ? "" : cell.text();
                out.append(c > s.c0() ? "\t" : "").append(v);
            }
            out.append('\n');
        }
        return out.toString();
    }

    /** Copies the selected cells to the clipboard (nothing while no table is shown). */
    void copy() {
        if (pane.table() == null) {
            return;
        }
        Clipboard cb = new Clipboard(grid.control().getDisplay());
        try {
            cb.setContents(new Object[] {copyText()}, new Transfer[] {TextTransfer.getInstance()});
        } finally {
            cb.dispose();
        }
    }
}
