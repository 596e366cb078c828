package org.parpe.gui.grid;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import org.parpe.core.edit.Replacement;

/**
 * Turns edits of the grid into one {@link Replacement} of the document that touches only the table's
 * rows and its {@code times} value, so the rest of the file keeps its comments and layout.
 * Changing entries keeps each one in its place: a new entry is right-aligned in the room the old
 * one had (its spaces included), so aligned columns stay aligned. Adding or removing rows and
 * columns writes the rows again, one per line, each column right-aligned to its widest entry,
 * at the indentation of the first row.
 */
public final class TableEdits {
    /** Row index used for the {@code times} entries in a map of edits. */
    public static final int TIMES = -1;

    private TableEdits() {
    }

    /** A grid position: {@code row} ({@link #TIMES} for the times), {@code column}. */
    public record At(int row, int column) {
    }

    /**
     * Sets the entries in {@code values}; entries past a row's end are appended (the gap filled
     * with 0). A time set on a table without {@code times} adds the attribute, 1 for the other rows.
     */
    public static Replacement setCells(String doc, GaitTable t, Map<At, String> values) {
        List<Replacement> edits = new ArrayList<>();
        for (var e : values.entrySet()) {
            At at = e.getKey();
            String value = e.getValue().trim();
            if (at.row() == TIMES) {
                if (t.times() == null || at.column() >= t.times().size()) {
                    continue;
                }
                edits.add(replaceIn(doc, t.times().get(at.column()), Entities.encodeAttribute(value)));
            } else {
                List<Cell> row = t.rows().get(at.row());
                if (at.column() < row.size()) {
                    edits.add(replaceIn(doc, row.get(at.column()), Entities.encode(value)));
                } else {
                    edits.add(append(row, at.column(), Entities.encode(value)));
                }
            }
        }
        if (values.keySet().stream().anyMatch(a -> a.row() == TIMES) && t.times() == null) {
            String times = String.join(", ", mergedTimes(t, values).stream().map(Entities::encodeAttribute).toList());
            edits.add(new Replacement(t.attrInsert(), 0, " times=\"" + times + "\""));
        }
        return apply(doc, edits);
    }

    private static Replacement replaceIn(String doc, Cell c, String value) {
        String lead = doc.substring(c.slotStart(), c.start());
        int room = lead.length() + (c.end() - c.start());
        String newLead;
        if (lead.isEmpty()) {
            newLead = "";
        } else if (lead.indexOf('\n') >= 0) {
            newLead = lead;
        } else if (value.length() + 1 <= room) {
            newLead = " ".repeat(room - value.length());
        } else {
            newLead = " ";
        }
        return new Replacement(c.slotStart(), c.end() - c.slotStart(), newLead + value);
    }

    private static Replacement append(List<Cell> row, int column, String value) {
        Cell last = row.get(row.size() - 1);
        StringBuilder s = new StringBuilder();
        for (int c = row.size(); c < column; c++) {
            s.append(", 0");
        }
        s.append(", ").append(value);
        return new Replacement(last.end(), 0, s.toString());
    }

    private static Replacement apply(String doc, List<Replacement> edits) {
        if (edits.isEmpty()) {
            return new Replacement(0, 0, "");
        }
        edits.sort(Comparator.comparingInt(Replacement::offset));
        int from = edits.get(0).offset();
        int to = edits.stream().mapToInt(Replacement::end).max().orElse(from);
        StringBuilder out = new StringBuilder();
        int at = from;
        for (Replacement e : edits) {
            out.append(doc, at, e.offset()).append(e.text());
            at = e.end();
        }
        out.append(doc, at, to);
        return Replacement.between(from, doc.substring(from, to), out.toString());
    }

    private static List<String> mergedTimes(GaitTable t, Map<At, String> values) {
        List<String> times = new ArrayList<>();
        while (times.size() < t.rows().size()) {
            times.add("1");
        }
        values.forEach((at, v) -> {
            if (at.row() == TIMES && at.column() < times.size()) {
                times.set(at.column(), v.trim());
            }
        });
        return times;
    }

    /** Inserts a copy of row {@code copyOf} at {@code at} (its time copied too). */
    public static Replacement insertRow(String doc, GaitTable t, int at, int copyOf) {
        List<List<String>> rows = new ArrayList<>(t.texts());
        rows.add(at, rows.get(copyOf));
        List<String> times = t.times() == null ? null : new ArrayList<>(t.timeTexts());
        if (times != null) {
            times.add(Math.min(at, times.size()), copyOf < times.size() ? times.get(copyOf) : "1");
        }
        return rewrite(doc, t, rows, times);
    }

    /** Removes the rows {@code from..to} (inclusive) and their times; a table keeps at least one row. */
    public static Replacement deleteRows(String doc, GaitTable t, int from, int to) {
        List<List<String>> rows = new ArrayList<>(t.texts());
        List<String> times = t.times() == null ? null : new ArrayList<>(t.timeTexts());
        for (int r = Math.min(to, rows.size() - 1); r >= from && rows.size() > 1; r--) {
            rows.remove(r);
            if (times != null && r < times.size()) {
                times.remove(r);
            }
        }
        return rewrite(doc, t, rows, times);
    }

    /** Inserts a column at {@code at} in every row, holding a copy of column {@code copyOf} (0 where a row has none). */
    public static Replacement insertColumn(String doc, GaitTable t, int at, int copyOf) {
        List<List<String>> rows = new ArrayList<>();
        for (List<String> r : t.texts()) {
            List<String> row = new ArrayList<>(r);
            String v = copyOf >= 0 && copyOf < row.size() ? row.get(copyOf) : "0";
            row.add(Math.min(at, row.size()), v);
            rows.add(row);
        }
        return rewrite(doc, t, rows, t.timeTexts());
    }

    /** Removes the columns {@code from..to} (inclusive) from every row; each row keeps at least one entry. */
    public static Replacement deleteColumns(String doc, GaitTable t, int from, int to) {
        List<List<String>> rows = new ArrayList<>();
        for (List<String> r : t.texts()) {
            List<String> row = new ArrayList<>(r);
            for (int c = Math.min(to, row.size() - 1); c >= from && row.size() > 1; c--) {
                row.remove(c);
            }
            rows.add(row);
        }
        return rewrite(doc, t, rows, t.timeTexts());
    }

    /** Writes the rows (and the times, when not {@code null}) again, aligned. */
    static Replacement rewrite(String doc, GaitTable t, List<List<String>> rows, List<String> times) {
        String region = doc.substring(t.start(), t.end());
        String indent = indent(doc, t);
        int last = region.length();
        while (last > 0 && Character.isWhitespace(region.charAt(last - 1))) {
            last--;
        }
        String tail = region.substring(last);
        if (tail.indexOf('\n') < 0) {
            tail = "\n" + lineIndent(doc, t.attrInsert());
        }
        int[] widths = new int[rows.stream().mapToInt(List::size).max().orElse(0)];
        for (List<String> row : rows) {
            for (int c = 0; c < row.size(); c++) {
                widths[c] = Math.max(widths[c], Entities.encode(row.get(c)).length());
            }
        }
        StringBuilder out = new StringBuilder();
        for (List<String> row : rows) {
            out.append('\n').append(indent);
            for (int c = 0; c < row.size(); c++) {
                String v = Entities.encode(row.get(c));
                out.append(c == 0 ? "" : ", ").append(" ".repeat(widths[c] - v.length())).append(v);
            }
        }
        out.append(tail);
        String newDoc = doc.substring(0, t.start()) + out + doc.substring(t.end());
        int from = t.start();
        if (times != null) {
            String value = String.join(", ", times.stream().map(Entities::encodeAttribute).toList());
            if (t.times() != null) {
                newDoc = doc.substring(0, t.timesStart()) + value + newDoc.substring(t.timesEnd());
                from = t.timesStart();
            } else {
                newDoc = doc.substring(0, t.attrInsert()) + " times=\"" + value + "\"" + newDoc.substring(t.attrInsert());
                from = t.attrInsert();
            }
        }
        int tailLen = doc.length() - t.end();
        return Replacement.between(from, doc.substring(from, t.end()), newDoc.substring(from, newDoc.length() - tailLen));
    }

    /** The smallest indentation of the rows that start their line, else the start tag's plus two spaces. */
    private static String indent(String doc, GaitTable t) {
        String best = null;
        for (List<Cell> row : t.rows()) {
            int first = row.get(0).start();
            int ls = doc.lastIndexOf('\n', first - 1) + 1;
            if (ls >= t.start() && doc.substring(ls, first).isBlank() && (best == null || first - ls < best.length())) {
                best = doc.substring(ls, first);
            }
        }
        return best != null ? best : lineIndent(doc, t.attrInsert()) + "  ";
    }

    private static String lineIndent(String doc, int offset) {
        int ls = doc.lastIndexOf('\n', offset - 1) + 1;
        int e = ls;
        while (e < doc.length() && (doc.charAt(e) == ' ' || doc.charAt(e) == '\t')) {
            e++;
        }
        return doc.substring(ls, e);
    }
}
