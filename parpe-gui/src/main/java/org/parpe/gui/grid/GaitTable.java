package org.parpe.gui.grid;

import java.util.List;

/**
 * A gait table found in the text (PARSL.md §6): its rows of entries and, if written, its
 * {@code times} entries, with their places in the document.
 *
 * @param name          the automaton's name
 * @param line          the 1-based line of the automaton's start tag
 * @param attrInsert    document offset just after the element name (where a new attribute goes)
 * @param start         document offset where the rows' text starts (after the start tag)
 * @param end           document offset where it ends (at the next tag or comment)
 * @param rows          the rows, each a list of entries
 * @param times         the {@code times} entries, or {@code null} when the attribute is absent
 * @param timesStart    document offset of the {@code times} value, or -1
 * @param timesEnd      document offset after the {@code times} value, or -1
 * @param readOnly      why the grid cannot edit this table (markup inside the rows), or {@code null}
 */
public record GaitTable(String name, int line, int attrInsert, int start, int end, List<List<Cell>> rows,
                        List<Cell> times, int timesStart, int timesEnd, String readOnly) {

    public GaitTable {
        rows = rows.stream().map(List::copyOf).toList();
        times = times == null ? null : List.copyOf(times);
    }

    /** The number of columns: the widest row. */
    public int width() {
        return rows.stream().mapToInt(List::size).max().orElse(0);
    }

    /** The entry at row {@code r}, column {@code c}, or {@code null} when the row is shorter. */
    public Cell cell(int r, int c) {
        List<Cell> row = rows.get(r);
        return c < row.size() ? row.get(c) : null;
    }

    /** The texts of the rows, as the grid shows them. */
    public List<List<String>> texts() {
        return rows.stream().map(row -> row.stream().map(Cell::text).toList()).toList();
    }

    /** The {@code times} texts, or {@code null}. */
    public List<String> timeTexts() {
        return times == null ? null : times.stream().map(Cell::text).toList();
    }
}
