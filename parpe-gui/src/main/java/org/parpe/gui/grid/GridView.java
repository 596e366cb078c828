package org.parpe.gui.grid;

import java.util.List;
import java.util.Map;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.TableEditor;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.eclipse.swt.widgets.TableItem;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.grid.Fill.Selection;
import org.parpe.gui.text.PanelMsg;

/**
 * The grid widget: an SWT table whose first column numbers the rows, then one column per grid
 * column (the times, then the modules). Cells are selected as a rectangle (click, shift-click,
 * drag, arrow keys with or without shift; a click on a step number takes the row's modules) and edited in place (double-click, Enter, F2 or simply
 * typing; Enter or Tab commits, Esc cancels). Cells with a problem are tinted and show the
 * problem as a tooltip. UI thread only.
 */
final class GridView {
    static final Color SELECTED = org.parpe.gui.panels.Theme.pick(0xC8DAF4, 0x2F4A6E);
    static final Color INVALID = org.parpe.gui.panels.Theme.pick(0xF8C8C8, 0x6E2F2F);
    static final Color INVALID_SELECTED = org.parpe.gui.panels.Theme.pick(0xE8B0C8, 0x6E2F55);
    static final Color ABSENT = org.parpe.gui.panels.Theme.pick(0xEEEEEE, 0x3A3A3A);
    private static final int MIN_WIDTH = 30;
    /** Room around a column's text: cell margins and the header's sort/resize area. */
    private static final int PADDING = 12;

    /** What the grid asks its owner to do. */
    interface Actions {
        /** The user entered {@code text} into the cell at {@code row}, grid column {@code column}. */
        void edited(int row, int column, String text);

        /** The focused cell moved to {@code row}, grid column {@code column}. */
        void focused(int row, int column);

        /** Ctrl+C in the grid. */
        void copy();

        /** Ctrl+V in the grid. */
        void paste();
    }

    private final Table table;
    private final TableEditor cellEditor;
    private final Actions actions;
    private List<String> headers = List.of();
    private List<List<String>> cells = List.of();
    private Map<Long, String> problems = Map.of();
    private boolean[] absent = new boolean[0];
    private boolean editable;
    private int anchorRow;
    private int anchorCol;
    private int focusRow;
    private int focusCol;
    private Text text;
    private int editRow;
    private int editCol;

    GridView(Composite parent, Actions actions) {
        this.actions = actions;
        table = new Table(parent, SWT.BORDER | SWT.V_SCROLL | SWT.H_SCROLL);
        table.setHeaderVisible(true);
        table.setLinesVisible(true);
        table.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        cellEditor = new TableEditor(table);
        cellEditor.grabHorizontal = true;
        cellEditor.grabVertical = true;
        table.addListener(SWT.MouseDown, this::mouseDown);
        table.addListener(SWT.MouseMove, e -> {
            Point cell = cellAt(e.x, e.y);
            if ((e.stateMask & SWT.BUTTON1) != 0 && cell != null) {
                select(anchorRow, anchorCol, cell.y, cell.x);
            }
            String tip = cell == null ? null : problems.get(key(cell.y, cell.x));
            if (!java.util.Objects.equals(tip, table.getToolTipText())) {
                table.setToolTipText(tip);
            }
        });
        table.addListener(SWT.MouseDoubleClick, e -> {
            Point cell = cellAt(e.x, e.y);
            if (cell != null) {
                edit(cell.y, cell.x, null);
            }
        });
        table.addListener(SWT.Selection, e -> table.deselectAll());
        table.addListener(SWT.KeyDown, this::key);
    }

    Table control() {
        return table;
    }

    private static long key(int row, int column) {
        return ((long) row << 32) | column;
    }

    /** Key of a cell in the problem map given to {@link #show}. */
    static long cellKey(int row, int column) {
        return key(row, column);
    }

    /**
     * Shows {@code rows} of cells under {@code headers} (one per grid column); {@code problems}
     * maps {@link #cellKey} to the message shown for the cell; {@code absentColumns} marks
     * columns shown in grey (times not written).
     */
    void show(List<String> headers, List<List<String>> rows, Map<Long, String> problems, boolean[] absentColumns,
              boolean editable) {
        // A cell being typed into stays open (a validation finishing must not drop the typing)
        // unless its cell is gone.
        if (!editable || editRow >= rows.size() || editCol >= headers.size()) {
            cancelEdit();
        }
        this.headers = headers;
        this.cells = rows;
        this.problems = problems;
        this.absent = absentColumns;
        this.editable = editable;
        table.setRedraw(false);
        try {
            setColumns(headers);
            table.setItemCount(rows.size());
            for (int r = 0; r < rows.size(); r++) {
                TableItem it = table.getItem(r);
                it.setText(0, Integer.toString(r));
                for (int c = 0; c < headers.size(); c++) {
                    it.setText(c + 1, c < rows.get(r).size() ? rows.get(r).get(c) : "");
                }
            }
            fitColumns(headers, rows);
            table.setToolTipText(null);
            focusRow = clamp(focusRow, rows.size());
            anchorRow = clamp(anchorRow, rows.size());
            focusCol = clamp(focusCol, headers.size());
            anchorCol = clamp(anchorCol, headers.size());
            paint();
        } finally {
            table.setRedraw(true);
        }
    }

    /**
     * Shows the text {@code steps} × 2 points larger than the normal font and fits the columns to
     * it: a column as wide as its text in the normal font would cut the last digit of a larger one.
     */
    void zoom(int steps) {
        org.parpe.gui.panels.Zoom.apply(table, table.getDisplay().getSystemFont(), steps);
        if (text != null && !text.isDisposed()) {
            text.setFont(table.getFont());
        }
        if (table.getColumnCount() == headers.size() + 2) {
            fitColumns(headers, cells);
        }
    }

    /** Makes each column as wide as its widest text (header or cell), at least {@value #MIN_WIDTH} pixels. */
    private void fitColumns(List<String> headers, List<List<String>> rows) {
        GC gc = new GC(table);
        try {
            int[] w = new int[headers.size() + 1];
            w[0] = gc.textExtent(PanelMsg.GRID_STEP.text()).x;
            for (int c = 0; c < headers.size(); c++) {
                w[c + 1] = gc.textExtent(headers.get(c)).x;
            }
            for (int r = 0; r < rows.size(); r++) {
                w[0] = Math.max(w[0], gc.textExtent(Integer.toString(r)).x);
                for (int c = 0; c < Math.min(headers.size(), rows.get(r).size()); c++) {
                    w[c + 1] = Math.max(w[c + 1], gc.textExtent(rows.get(r).get(c)).x);
                }
            }
            for (int i = 0; i < w.length; i++) {
                table.getColumn(i).setWidth(Math.max(MIN_WIDTH, w[i] + PADDING));
            }
        } finally {
            gc.dispose();
        }
    }

    /**
     * The step numbers, a column per grid column, and an empty one that takes the room left
     * (GTK stretches the last column; the last module's should look like the others).
     */
    private void setColumns(List<String> headers) {
        while (table.getColumnCount() > headers.size() + 2) {
            table.getColumn(table.getColumnCount() - 1).dispose();
        }
        while (table.getColumnCount() < headers.size() + 2) {
            new TableColumn(table, SWT.RIGHT);
        }
        table.getColumn(0).setText(PanelMsg.GRID_STEP.text());
        table.getColumn(0).setToolTipText(PanelMsg.GRID_STEP_TIP.text());
        for (int i = 0; i < headers.size(); i++) {
            String h = headers.get(i);
            table.getColumn(i + 1).setText(h);
            table.getColumn(i + 1).setToolTipText(i == 0 ? PanelMsg.GRID_TIMES_TIP.text()
                    : h.chars().allMatch(Character::isDigit) ? PanelMsg.POSE_MODULE.text(h) : null);
        }
        TableColumn filler = table.getColumn(headers.size() + 1);
        filler.setText("");
        filler.setWidth(12);
    }

    private static int clamp(int v, int n) {
        return Math.max(0, Math.min(v, n - 1));
    }

    /** The number of grid columns (without the step numbers and the filler). */
    private int columns() {
        return Math.max(0, table.getColumnCount() - 2);
    }

    /** The selected rectangle, in rows and grid columns. */
    Selection selection() {
        return new Selection(Math.min(anchorRow, focusRow), Math.min(anchorCol, focusCol),
                Math.max(anchorRow, focusRow), Math.max(anchorCol, focusCol));
    }

    /** Selects from the anchor cell to the focus cell. */
    void select(int aRow, int aCol, int fRow, int fCol) {
        anchorRow = clamp(aRow, cells.size());
        anchorCol = clamp(aCol, columns());
        focusRow = clamp(fRow, cells.size());
        focusCol = clamp(fCol, columns());
        paint();
        if (focusRow >= 0 && focusRow < table.getItemCount()) {
            table.showItem(table.getItem(focusRow));
            table.showColumn(table.getColumn(focusCol + 1));
            actions.focused(focusRow, focusCol);
        }
    }

    private void paint() {
        Selection s = selection();
        Color normal = table.getBackground();
        for (int r = 0; r < table.getItemCount(); r++) {
            TableItem it = table.getItem(r);
            it.setBackground(0, ABSENT);
            for (int c = 0; c < columns(); c++) {
                boolean sel = s.contains(r, c);
                boolean bad = problems.containsKey(key(r, c));
                it.setBackground(c + 1, bad ? (sel ? INVALID_SELECTED : INVALID)
                        : sel ? SELECTED : c < absent.length && absent[c] ? ABSENT : normal);
            }
        }
    }

    /** The cell under a point: x = grid column, y = row; {@code null} off the cells. */
    private Point cellAt(int x, int y) {
        TableItem it = table.getItem(new Point(x, y));
        if (it == null) {
            return null;
        }
        for (int c = 1; c <= columns(); c++) {
            if (it.getBounds(c).contains(x, y)) {
                return new Point(c - 1, table.indexOf(it));
            }
        }
        return null;
    }

    private void mouseDown(Event e) {
        if (e.button != 1) {
            return;
        }
        TableItem item = table.getItem(new Point(e.x, e.y));
        if (item != null && item.getBounds(0).contains(e.x, e.y) && columns() > 1) {
            // The step number selects the row's module cells (shift: down to this row).
            int row = table.indexOf(item);
            select((e.stateMask & SWT.SHIFT) != 0 ? anchorRow : row, 1, row, columns() - 1);
            return;
        }
        Point cell = cellAt(e.x, e.y);
        if (cell == null) {
            return;
        }
        if ((e.stateMask & SWT.SHIFT) != 0) {
            select(anchorRow, anchorCol, cell.y, cell.x);
        } else {
            select(cell.y, cell.x, cell.y, cell.x);
        }
    }

    private void key(Event e) {
        boolean shift = (e.stateMask & SWT.SHIFT) != 0;
        int dr = e.keyCode == SWT.ARROW_DOWN ? 1 : e.keyCode == SWT.ARROW_UP ? -1 : 0;
        int dc = e.keyCode == SWT.ARROW_RIGHT ? 1 : e.keyCode == SWT.ARROW_LEFT ? -1 : 0;
        if (dr != 0 || dc != 0) {
            int r = focusRow + dr;
            int c = focusCol + dc;
            if (shift) {
                select(anchorRow, anchorCol, r, c);
            } else {
                select(r, c, r, c);
            }
            e.doit = false;
        } else if ((e.stateMask & SWT.MOD1) != 0 && (e.keyCode == 'c' || e.keyCode == 'v')) {
            if (e.keyCode == 'c') {
                actions.copy();
            } else {
                actions.paste();
            }
            e.doit = false;
        } else if (e.keyCode == SWT.CR || e.keyCode == SWT.KEYPAD_CR || e.keyCode == SWT.F2) {
            edit(focusRow, focusCol, null);
            e.doit = false;
        } else if ((e.stateMask & (SWT.MOD1 | SWT.ALT)) == 0 && e.character > ' ' && e.character != SWT.DEL) {
            edit(focusRow, focusCol, String.valueOf(e.character));
            e.doit = false;
        }
    }

    /**
     * Opens the in-place editor on a cell, holding the cell's text or {@code initial} (typing
     * starts a new entry). Nothing happens when the table cannot be edited.
     */
    void edit(int row, int column, String initial) {
        if (!editable || row < 0 || row >= table.getItemCount() || column < 0 || column >= columns()) {
            return;
        }
        cancelEdit();
        select(row, column, row, column);
        Text t = new Text(table, SWT.SINGLE | SWT.RIGHT);
        t.setFont(table.getFont());
        text = t;
        editRow = row;
        editCol = column;
        String old = column < cells.get(row).size() ? cells.get(row).get(column) : "";
        t.setText(initial != null ? initial : old);
        t.setSelection(initial != null ? t.getText().length() : 0, t.getText().length());
        t.addListener(SWT.DefaultSelection, e -> commit(t, row, column, 1, 0));
        t.addListener(SWT.FocusOut, e -> commit(t, row, column, 0, 0));
        t.addListener(SWT.Traverse, e -> {
            if (e.detail == SWT.TRAVERSE_ESCAPE) {
                e.doit = false;
                cancelEdit();
                table.setFocus();
            } else if (e.detail == SWT.TRAVERSE_TAB_NEXT || e.detail == SWT.TRAVERSE_TAB_PREVIOUS) {
                e.doit = false;
                commit(t, row, column, 0, e.detail == SWT.TRAVERSE_TAB_NEXT ? 1 : -1);
            }
        });
        cellEditor.setEditor(t, table.getItem(row), column + 1);
        t.setFocus();
    }

    /** The open in-place editor, or {@code null}. */
    Text editor() {
        return text == null || text.isDisposed() ? null : text;
    }

    private void commit(Text t, int row, int column, int down, int right) {
        if (t != text || t.isDisposed()) {
            return;
        }
        String value = t.getText();
        text = null;
        t.dispose();
        select(row + down, column + right, row + down, column + right);
        table.setFocus();
        String old = column < cells.get(row).size() ? cells.get(row).get(column) : "";
        if (!value.trim().equals(old)) {
            actions.edited(row, column, value);
        }
    }

    private void cancelEdit() {
        Text t = text;
        text = null;
        if (t != null && !t.isDisposed()) {
            t.dispose();
        }
    }
}
