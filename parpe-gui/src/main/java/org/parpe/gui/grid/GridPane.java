package org.parpe.gui.grid;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.eclipse.jface.text.BadLocationException;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.edit.Replacement;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.lang.Numbers;
import org.parpe.core.load.ListItem;
import org.parpe.core.model.Program;
import org.parpe.gui.editor.AfterChange;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.grid.Fill.Selection;
import org.parpe.gui.grid.TableEdits.At;
import org.parpe.gui.panels.OverflowBar;
import org.parpe.gui.panels.Zoom;
import org.parpe.gui.text.PanelMsg;

/**
 * The grid editor beside the text: when the script holds a gait table, the table is shown as a
 * grid (rows = time steps, a column for the {@code times}, then one column per module of the
 * group the table runs on) and kept in step with the text both ways. Every grid edit is one
 * replacement of the table's own range in the editor's document, so the rest of the file keeps
 * its comments and layout and Edit → Undo takes it back. Cells the script's diagnostics point
 * into are tinted and carry the same message. Hidden while the script has no gait table. UI
 * thread only.
 */
public final class GridPane implements GridView.Actions {
    private static final String TIMES = "times";
    /** The background of a cell with a problem (not selected). */
    public static final Color INVALID = GridView.INVALID;

    private final SashForm sash;
    private final Control text;
    private final ParslEditor editor;
    /** The widest table the grid shows (each column is a widget made on the UI thread). */
    public static final int MAX_COLUMNS = 400;
    private final Composite box;
    private final Composite bar;
    private final Combo choice;
    private final GridView grid;
    private final GridClipboard clipboard;
    private final Label status;
    private final List<Button> commands = new ArrayList<>();
    private List<GaitTable> tables = List.of();
    private GaitTable table;
    private String chosen;
    private boolean stale;
    private boolean following;
    private Program program;
    private List<Diagnostic> diagnostics = List.of();
    private double amplitude = 15;
    private double phaseStep = -0.125;
    private Consumer<Boolean> shown = v -> { };

    /** Adds the grid to {@code sash}, beside the editor's control (already in it). */
    public GridPane(SashForm sash, ParslEditor editor) {
        this.sash = sash;
        this.editor = editor;
        this.text = editor.viewer().getControl();
        box = new Composite(sash, SWT.NONE);
        GridLayout gl = new GridLayout(1, false);
        gl.marginWidth = 2;
        gl.marginHeight = 2;
        box.setLayout(gl);
        // One row whatever the width: the buttons that do not fit go behind a chevron (»), they never wrap.
        bar = new OverflowBar(box).control();
        bar.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        new Label(bar, SWT.NONE).setText(PanelMsg.GRID_GAIT_TABLE.text());
        choice = new Combo(bar, SWT.READ_ONLY);
        choice.addListener(SWT.Selection, e -> {
            chosen = choice.getText();
            refresh();
        });
        command(bar, PanelMsg.GRID_ADD_ROW.text(), PanelMsg.GRID_ADD_ROW_TIP.text(), this::insertRow);
        command(bar, PanelMsg.GRID_REMOVE_ROWS.text(), PanelMsg.GRID_REMOVE_ROWS_TIP.text(), this::deleteRows);
        command(bar, PanelMsg.GRID_ADD_COLUMN.text(), PanelMsg.GRID_ADD_COLUMN_TIP.text(), this::insertColumn);
        command(bar, PanelMsg.GRID_REMOVE_COLUMNS.text(), PanelMsg.GRID_REMOVE_COLUMNS_TIP.text(), this::deleteColumns);
        command(bar, PanelMsg.GRID_WAVE.text(), PanelMsg.GRID_WAVE_TIP.text(), this::askWave);
        command(bar, PanelMsg.GRID_PASTE.text(), PanelMsg.GRID_PASTE_TIP.text(), this::paste);
        grid = new GridView(box, this);
        clipboard = new GridClipboard(this, grid);
        status = new Label(box, SWT.WRAP);
        status.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        sash.setWeights(40, 60);
        sash.setMaximizedControl(text);
        editor.widget().addCaretListener(e -> caretAt(e.caretOffset));
        new AfterChange(box, editor.document(), this::refresh);
    }

    private void command(Composite bar, String label, String tip, Runnable action) {
        Button b = new Button(bar, SWT.PUSH);
        b.setText(label);
        b.setToolTipText(tip);
        b.addListener(SWT.Selection, e -> action.run());
        commands.add(b);
    }

    /** Reads the tables from the text again and shows the chosen one. */
    void refresh() {
        // A text over the colouring limit is not parsed at every keystroke: it shows no grid.
        List<GaitTable> found = editor.document().getLength() > ParslEditor.COLOUR_LIMIT ? List.of()
                : TableText.find(editor.document().get());
        stale = found == null;
        if (found != null) {
            tables = found;
        }
        table = tables.stream().filter(t -> t.name().equals(chosen)).findFirst()
                .orElse(tables.isEmpty() ? null : tables.get(0));
        chosen = table == null ? null : table.name();
        List<String> names = tables.stream().map(GaitTable::name).toList();
        if (!names.equals(List.of(choice.getItems()))) {
            choice.setItems(names.toArray(String[]::new));
            choice.getParent().layout();
        }
        if (table == null) {
            setShown(false);
            return;
        }
        choice.select(names.indexOf(chosen));
        setShown(true);
        show();
    }

    private void show() {
        List<Integer> modules = Modules.of(program, table.name());
        int width = table.width();
        int columns = width == 1 && modules != null ? 1 : Math.max(width, modules == null ? 0 : modules.size());
        if (columns > MAX_COLUMNS) {
            // A row of thousands of entries would make as many table columns on the UI thread (minutes):
            // the grid says so and the text stays the place to edit it.
            grid.show(List.of(TIMES), List.of(), Map.of(), new boolean[] {true}, false);
            for (Button b : commands) {
                b.setEnabled(false);
            }
            status.setText(PanelMsg.GRID_TOO_WIDE.text(table.name(), table.rows().size(), columns, MAX_COLUMNS));
            box.layout();
            return;
        }
        List<String> headers = new ArrayList<>();
        headers.add(TIMES);
        for (int c = 0; c < columns; c++) {
            headers.add(width == 1 && modules != null ? PanelMsg.GRID_ALL.text() : modules != null && c < modules.size()
                    ? Integer.toString(modules.get(c)) : "#" + (c + 1));
        }
        List<List<String>> rows = new ArrayList<>();
        List<String> times = table.timeTexts();
        // Without times="…" every row gets an equal share of the period: show it in seconds (lesson 2's
        // 0.5 s), not a bare "1" that reads as one second.
        Double share = times == null ? Modules.secondsPerRow(program, table.name(), table.rows().size()) : null;
        String equal = share == null ? PanelMsg.GRID_EQUAL.text() : Numbers.format(share) + " s";
        for (int r = 0; r < table.rows().size(); r++) {
            List<String> row = new ArrayList<>();
            row.add(times == null ? equal : r < times.size() ? times.get(r) : "");
            row.addAll(table.texts().get(r));
            rows.add(row);
        }
        Map<Long, String> problems = new HashMap<>();
        List<String> others = new ArrayList<>();
        CellProblems.place(editor.document(), table, diagnostics, problems, others);
        boolean[] absent = new boolean[headers.size()];
        absent[0] = times == null;
        grid.show(headers, rows, problems, absent, editable());
        for (Button b : commands) {
            b.setEnabled(editable());
        }
        status.setText(describe(columns, modules != null, problems.size(), others));
        box.layout();
    }

    /** Whether the table shown can be edited here (it is read, and not read-only). */
    boolean editable() {
        return table != null && table.readOnly() == null && !stale;
    }

    private String describe(int columns, boolean used, int bad, List<String> others) {
        if (stale) {
            return PanelMsg.GRID_STALE.text();
        }
        if (table.readOnly() != null) {
            return PanelMsg.GRID_READ_ONLY.text(table.readOnly());
        }
        StringBuilder s = new StringBuilder((columns == 1 ? PanelMsg.GRID_SIZE_ONE_COLUMN : PanelMsg.GRID_SIZE).text(table.name(),
                table.rows().size(), columns, (used ? PanelMsg.GRID_HEADERS_MODULES : PanelMsg.GRID_NOT_USED).text())
                + (table.times() == null ? PanelMsg.GRID_NO_TIMES.text() : ""));
        if (bad > 0) {
            s.append("\n").append((bad == 1 ? PanelMsg.GRID_ONE_BAD_CELL : PanelMsg.GRID_BAD_CELLS).text(bad));
        }
        for (String o : others.subList(0, Math.min(3, others.size()))) {
            s.append("\n").append(o);
        }
        return s.toString();
    }

    private void setShown(boolean v) {
        if (v != (sash.getMaximizedControl() == null)) {
            sash.setMaximizedControl(v ? null : text);
            shown.accept(v);
        }
    }

    /** {@code listener} learns when the grid appears beside the text (true) or goes (false). */
    public void onShown(Consumer<Boolean> listener) {
        shown = listener;
    }

    /** The program last loaded, for the modules of the table's group. */
    public void setProgram(Program p) {
        program = p;
        refresh();
    }

    /** The diagnostics of this file (those the editor marks). */
    public void setDiagnostics(List<Diagnostic> ds) {
        diagnostics = List.copyOf(ds);
        if (table != null) {
            show();
        }
    }

    /** Shows the gait table called {@code name}; false if the script has none of that name. */
    public boolean showTable(String name) {
        chosen = name;
        refresh();
        return table != null && table.name().equals(name);
    }

    /** The names of the script's gait tables, as last read from the text. */
    public List<String> tableNames() {
        return tables.stream().map(GaitTable::name).toList();
    }

    /** The table shown, as last read from the text, or {@code null}. */
    public GaitTable table() {
        return table;
    }

    /** The bar of the table's buttons (tests). */
    public Composite toolBar() {
        return bar;
    }

    /** Whether the grid is shown beside the editor. */
    public boolean visible() {
        return table != null && sash.getMaximizedControl() == null;
    }

    /** The grid's table widget. */
    public Table widget() {
        return grid.control();
    }

    /**
     * Shows the grid's text {@code steps} × 2 points larger than normal (the window's zoom,
     * {@link Zoom}); the columns widen or narrow with it.
     */
    public void zoom(int steps) {
        grid.zoom(steps);
    }

    /** The in-place cell editor while one is open, else {@code null}. */
    public Text cellEditor() {
        return grid.editor();
    }

    /** Selects rows {@code r0..r1}, grid columns {@code c0..c1} (column 0 is the times, 1 the first module). */
    public void select(int r0, int c0, int r1, int c1) {
        grid.select(r0, c0, r1, c1);
    }

    /** The selection, in rows and grid columns. */
    public Selection selection() {
        return grid.selection();
    }

    /** The text of the status line under the grid. */
    public String status() {
        return status.getText();
    }

    /** Shows the focused cell's entry selected in the text. */
    @Override
    public void focused(int row, int column) {
        if (table == null || row >= table.rows().size()) {
            return;
        }
        Cell c = column == 0 ? (table.times() != null && row < table.times().size() ? table.times().get(row) : null)
                : table.cell(row, column - 1);
        if (c != null && c.end() <= editor.document().getLength()) {
            following = true;
            try {
                editor.viewer().setSelectedRange(c.start(), c.end() - c.start());
                editor.viewer().revealRange(c.start(), c.end() - c.start());
            } finally {
                following = false;
            }
        }
    }

    /** The caret moved in the text: show the table it is in, if another. */
    private void caretAt(int offset) {
        if (following) {
            return;
        }
        for (GaitTable t : tables) {
            if (offset >= t.attrInsert() && offset <= t.end() && !t.name().equals(chosen)) {
                chosen = t.name();
                refresh();
                return;
            }
        }
    }

    @Override
    public void edited(int row, int column, String value) {
        writeCells(Map.of(at(row, column), value), 0);
    }

    /**
     * Writes {@code cells} into the table as one edit (values that would split an entry or a row
     * left out), and says on the status line what was left out, with the {@code outside} cells.
     */
    void writeCells(Map<At, String> cells, int outside) {
        int[] dropped = {0};
        apply(TableEdits.setCells(editor.document().get(), table, single(cells, dropped)));
        note(dropped[0], outside);
    }

    /** The table's place of grid cell {@code row, column} (column 0: the times). */
    static At at(int row, int column) {
        return column == 0 ? new At(TableEdits.TIMES, row) : new At(row, column - 1);
    }

    /**
     * Drops the values that hold a top-level {@code ,} or {@code ;} (they would split the entry
     * or the row: e.g. a decimal comma from a spreadsheet), counting them in {@code dropped}.
     */
    private static Map<At, String> single(Map<At, String> values, int[] dropped) {
        Map<At, String> out = new LinkedHashMap<>();
        for (var e : values.entrySet()) {
            String v = e.getValue();
            if (ListItem.ranges(v, 0, v.length(), ',').size() > 1 || ListItem.ranges(v, 0, v.length(), ';').size() > 1) {
                dropped[0]++;
            } else {
                out.put(e.getKey(), v);
            }
        }
        return out;
    }

    /** Adds to the status line what an edit left out. */
    private void note(int dropped, int outside) {
        String s = status.getText();
        if (dropped > 0) {
            s += "\n" + (dropped == 1 ? PanelMsg.GRID_ONE_DROPPED : PanelMsg.GRID_DROPPED).text(dropped);
        }
        if (outside > 0) {
            s += "\n" + PanelMsg.GRID_OUTSIDE.text(outside);
        }
        status.setText(s);
        box.layout();
    }

    private void apply(Replacement ch) {
        if (!editable() || ch.empty()) {
            return;
        }
        try {
            editor.document().replace(ch.offset(), ch.length(), ch.text());
        } catch (BadLocationException e) {
            status.setText(PanelMsg.DIAGRAM_CHANGED_MEANWHILE.text(e.getMessage()));
            return;
        }
        refresh();
    }

    /** Fills the selected module cells (all of them when one cell is selected) with a travelling wave. */
    public void fillWave(double a, double phi) {
        if (!editable()) {
            return;
        }
        Map<At, String> cells = new LinkedHashMap<>();
        Fill.wave(waveTarget(), a, phi).forEach((at, v) -> cells.put(new At(at.row(), at.column() - 1), v));
        apply(TableEdits.setCells(editor.document().get(), table, cells));
    }

    private Selection waveTarget() {
        Selection s = grid.selection();
        if (s.rows() == 1 && s.columns() == 1 || s.c1() == 0) {
            return new Selection(0, 1, table.rows().size() - 1, Math.max(1, table.width()));
        }
        return new Selection(s.r0(), Math.max(1, s.c0()), s.r1(), s.c1());
    }

    private void askWave() {
        if (table == null) {
            return;
        }
        Selection s = waveTarget();
        WaveDialog d = new WaveDialog(box.getShell(), PanelMsg.GRID_WAVE_TARGET.text(s.rows(), s.columns()), amplitude, phaseStep);
        if (d.open() == Window.OK) {
            amplitude = d.amplitude();
            phaseStep = d.phaseStep();
            fillWave(amplitude, phaseStep);
        }
    }

    /** Pastes {@code clip} (tab- or comma-separated lines) at the selection; returns how many cells fell outside. */
    public int paste(String clip) {
        return clipboard.paste(clip);
    }

    @Override
    public void paste() {
        clipboard.paste();
    }

    /** The selected cells as tab-separated lines, as a spreadsheet takes them. */
    public String copyText() {
        return clipboard.copyText();
    }

    @Override
    public void copy() {
        clipboard.copy();
    }

    /** Adds a copy of the focused row below the selection. */
    public void insertRow() {
        Selection s = grid.selection();
        if (editable()) {
            apply(TableEdits.insertRow(editor.document().get(), table, s.r1() + 1, s.r1()));
        }
    }

    /** Removes the selected rows (a table keeps one). */
    public void deleteRows() {
        Selection s = grid.selection();
        if (editable()) {
            apply(TableEdits.deleteRows(editor.document().get(), table, s.r0(), s.r1()));
        }
    }

    /** Adds a copy of the last selected module column after it. */
    public void insertColumn() {
        Selection s = grid.selection();
        if (editable()) {
            int c = Math.max(0, s.c1() - 1);
            apply(TableEdits.insertColumn(editor.document().get(), table, c + 1, c));
        }
    }

    /** Removes the selected module columns (each row keeps one entry). */
    public void deleteColumns() {
        Selection s = grid.selection();
        if (editable() && s.c1() >= 1) {
            apply(TableEdits.deleteColumns(editor.document().get(), table, Math.max(0, s.c0() - 1), s.c1() - 1));
        }
    }

    /** Whether the keyboard focus is in the grid (the Edit menu's clipboard items then act on it). */
    public boolean hasFocus() {
        return !grid.control().isDisposed() && grid.control().isFocusControl();
    }
}
