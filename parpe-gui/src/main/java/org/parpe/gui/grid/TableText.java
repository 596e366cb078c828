package org.parpe.gui.grid;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.load.ListItem;
import org.parpe.core.xml.SourceText;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XText;
import org.parpe.core.xml.XmlReader;
import org.parpe.gui.text.PanelMsg;

/**
 * Finds the gait tables of a script's text with the core's XML reader, which places every
 * character of element text and attribute values; the rows are then split as the loader splits
 * them (lines or {@code ;}, then top-level commas), on the text as written, so that each entry
 * keeps its exact range in the document (the reader's offsets: no line index of its own).
 */
public final class TableText {
    private final String text;

    private TableText(String text) {
        this.text = text;
    }

    /** The gait tables of {@code text} in document order, or {@code null} if it is not well-formed XML. */
    public static List<GaitTable> find(String text) {
        XElement root = XmlReader.read(new SourceText("grid", text), new DiagnosticList());
        if (root == null) {
            return null;
        }
        TableText t = new TableText(text);
        List<GaitTable> out = new ArrayList<>();
        for (XElement section : root.children()) {
            if (!section.name().equals("automata")) {
                continue;
            }
            for (XElement e : section.children()) {
                if (e.attr("states") == null && !e.texts().isEmpty()) {
                    out.add(t.table(e));
                }
            }
        }
        return out;
    }

    /** The offset the reader recorded for {@code p} (every place it gives has one). */
    private static int offset(SourcePos p) {
        return p.offset();
    }

    private GaitTable table(XElement e) {
        XText body = e.texts().get(0);
        int start = offset(body.posAt(0));
        int end = offset(body.posAt(body.value().length()));
        String readOnly = null;
        if (e.texts().size() > 1 || !e.children().isEmpty()) {
            readOnly = PanelMsg.GRID_ROWS_COMMENT.text(e.name());
        } else if (!Entities.decode(text.substring(start, end)).equals(body.value())) {
            readOnly = PanelMsg.GRID_ROWS_CDATA.text(e.name());
        }
        List<List<Cell>> rows = new ArrayList<>();
        for (int[] line : split(start, end, '\n')) {
            for (int[] part : split(line[0], line[1], ';')) {
                if (!text.substring(part[0], part[1]).isBlank()) {
                    rows.add(cells(part[0], part[1]));
                }
            }
        }
        XElement.XAttr times = e.attr("times");
        List<Cell> timeCells = null;
        int ts = -1;
        int te = -1;
        if (times != null) {
            XText v = times.value();
            ts = offset(v.posAt(0));
            te = offset(v.posAt(v.value().length()));
            timeCells = cells(ts, te);
        }
        int nameAt = offset(e.pos());
        return new GaitTable(e.name(), e.pos().line(), nameAt + e.name().length(), start, end, rows, timeCells, ts, te, readOnly);
    }

    private List<Cell> cells(int from, int to) {
        List<Cell> out = new ArrayList<>();
        for (int[] slot : split(from, to, ',')) {
            int s = slot[0];
            int t = slot[1];
            while (s < t && Character.isWhitespace(text.charAt(s))) {
                s++;
            }
            while (t > s && Character.isWhitespace(text.charAt(t - 1))) {
                t--;
            }
            out.add(new Cell(Entities.decode(text.substring(s, t)), s, t, slot[0], slot[1]));
        }
        return out;
    }

    /** The parts of {@code [from, to)} between top-level separators (not in parentheses or strings). */
    private List<int[]> split(int from, int to, char separator) {
        return ListItem.ranges(text, from, to, separator);
    }
}
