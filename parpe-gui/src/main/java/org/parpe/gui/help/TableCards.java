package org.parpe.gui.help;

import java.util.ArrayList;
import java.util.List;

/**
 * A table too wide for the tutorial's column, as one card per row: its first cells on a line,
 * each other cell on a line of its own after its column's name ("you will learn: …"), so that
 * a narrow column reads it without cells wrapping into each other's columns.
 */
final class TableCards {
    /** What a card's lines after its first start with. */
    static final String INDENT = "    ";

    private TableCards() {
    }

    /** The rows of {@code table} (a {@link Markdown.Kind#TABLE} block) as cards, its links and code kept. */
    static Markdown.Block cards(Markdown.Block table) {
        String[] rows = table.text().split("\n", -1);
        int head = Math.min(table.level(), rows.length);
        String[] names = head > 0 ? rows[head - 1].split("\t", -1) : new String[0];
        StringBuilder out = new StringBuilder();
        List<Markdown.Span> spans = new ArrayList<>();
        int rowStart = 0;
        for (int r = 0; r < rows.length; r++) {
            String[] cells = rows[r].split("\t", -1);
            if (r >= head) {
                if (out.length() > 0) {
                    out.append('\n');
                }
                int cellStart = rowStart;
                for (int c = 0; c < cells.length; c++) {
                    if (c == 1) {
                        out.append("  ");
                    } else if (c > 1) {
                        out.append('\n').append(INDENT);
                        String name = c < names.length ? names[c].strip() : "";
                        if (!name.isEmpty()) {
                            spans.add(new Markdown.Span(out.length(), name.length() + 1, Markdown.Style.ITALIC, null));
                            out.append(name).append(": ");
                        }
                    }
                    int shift = out.length() - cellStart;
                    for (Markdown.Span s : table.spans()) {
                        if (s.start() >= cellStart && s.start() + s.length() <= cellStart + cells[c].length()) {
                            spans.add(new Markdown.Span(s.start() + shift, s.length(), s.style(), s.target()));
                        }
                    }
                    out.append(cells[c]);
                    cellStart += cells[c].length() + 1;
                }
            }
            rowStart += rows[r].length() + 1;
        }
        return new Markdown.Block(Markdown.Kind.PARAGRAPH, 0, out.toString(), List.copyOf(spans), null);
    }
}
