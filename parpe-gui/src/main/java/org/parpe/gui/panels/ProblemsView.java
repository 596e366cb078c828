package org.parpe.gui.panels;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Consumer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.eclipse.swt.widgets.TableItem;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.gui.text.ToolMsg;

/**
 * The Problems view: the errors and warnings of the last validation of the text (load
 * diagnostics) and those of the last run (run diagnostics: run-time errors, overlap warnings,
 * parameter and control errors, robot configuration and bus faults), in one table sorted by
 * file, line and column. The two lists are kept apart: validating the text again replaces the
 * load diagnostics only, and only {@link #clearRunDiagnostics} (a new run) drops the run's.
 * Selecting a row (click, Enter, double-click) jumps to its place. The table is virtual, so a
 * script with a hundred thousand problems costs only the rows on screen. UI thread only.
 */
public final class ProblemsView {
    private static final Comparator<Diagnostic> BY_PLACE = Comparator
            .comparing((Diagnostic d) -> d.pos().file())
            .thenComparingInt(d -> d.pos().line())
            .thenComparingInt(d -> d.pos().column());

    private final Table table;
    private final Runnable changed;
    private List<Diagnostic> load = List.of();
    private List<Diagnostic> run = List.of();
    private List<Diagnostic> shown = List.of();
    /** How many equal run diagnostics each row of {@link #shown} stands for (1: itself alone). */
    private int[] repeats = new int[0];
    private final java.util.Map<Diagnostic, Integer> counts = new java.util.HashMap<>();

    /**
     * Creates the view.
     *
     * @param jump    receives the diagnostic the user picked
     * @param changed runs after the diagnostics shown changed (to update the editor's markers)
     */
    public ProblemsView(Composite parent, Consumer<Diagnostic> jump, Runnable changed) {
        this.changed = changed;
        Composite box = new Composite(parent, SWT.NONE);
        box.setLayout(new FillLayout());
        table = new Table(box, SWT.VIRTUAL | SWT.FULL_SELECTION | SWT.SINGLE | SWT.V_SCROLL | SWT.H_SCROLL);
        table.setHeaderVisible(true);
        table.setLinesVisible(true);
        column(ToolMsg.PROBLEMS_SEVERITY.text(), 110);
        column(ToolMsg.PROBLEMS_LOCATION.text(), 190);
        column(ToolMsg.PROBLEMS_DESCRIPTION.text(), 700);
        table.addListener(SWT.SetData, this::fill);
        // The description fills the rest of the width; a cut one is read whole in the tooltip.
        table.addListener(SWT.Resize, e -> {
            int rest = table.getClientArea().width - table.getColumn(0).getWidth() - table.getColumn(1).getWidth();
            table.getColumn(2).setWidth(Math.max(300, rest));
        });
        table.addListener(SWT.MouseHover, e -> {
            TableItem it = table.getItem(new org.eclipse.swt.graphics.Point(e.x, e.y));
            int i = it == null ? -1 : table.indexOf(it);
            table.setToolTipText(i < 0 || i >= shown.size() ? null : tip(shown.get(i)));
        });
        table.addListener(SWT.Selection, e -> pick(jump));
        table.addListener(SWT.DefaultSelection, e -> pick(jump));
    }

    private void column(String name, int width) {
        TableColumn c = new TableColumn(table, SWT.LEFT);
        c.setText(name);
        c.setWidth(width);
    }

    private void fill(Event e) {
        TableItem it = (TableItem) e.item;
        int i = table.indexOf(it);
        if (i < 0 || i >= shown.size()) {
            return;
        }
        Diagnostic d = shown.get(i);
        boolean err = d.severity() == Severity.ERROR;
        Icons icons = Icons.of(table.getDisplay());
        it.setImage(0, err ? icons.error : icons.warning);
        it.setText(0, isRun(d) ? ToolMsg.PROBLEMS_RUN_SEVERITY.text(severity(d)) : severity(d));
        it.setForeground(0, table.getDisplay().getSystemColor(err ? SWT.COLOR_RED : SWT.COLOR_DARK_YELLOW));
        it.setText(1, location(d.pos()));
        it.setText(2, d.message(repeats[i]));
    }

    /** Whether {@code d} came from the run (identity: an equal load diagnostic is a different row). */
    private boolean isRun(Diagnostic d) {
        for (Diagnostic r : run) {
            if (r == d) {
                return true;
            }
        }
        return false;
    }

    private void pick(Consumer<Diagnostic> jump) {
        int i = table.getSelectionIndex();
        if (i >= 0 && i < shown.size()) {
            jump.accept(shown.get(i));
        }
    }

    /** The top-level control. */
    public Composite control() {
        return table.getParent();
    }

    /** Shows the diagnostics of the latest validation of the text, keeping the run's. */
    public void setLoadDiagnostics(List<Diagnostic> diagnostics) {
        load = List.copyOf(diagnostics);
        refresh();
    }

    /** Shows the diagnostics of the current or last run beside the load diagnostics, replacing earlier run ones. */
    public void setRunDiagnostics(List<Diagnostic> diagnostics) {
        run = List.copyOf(diagnostics);
        refresh();
    }

    /** Drops the run diagnostics (a new run starts, or another file is opened). */
    public void clearRunDiagnostics() {
        if (!run.isEmpty()) {
            run = List.of();
            refresh();
        }
    }

    /**
     * Load and run diagnostics by place; equal run diagnostics (a bus warning said again and
     * again) fold into one row with their count.
     */
    private void refresh() {
        java.util.Map<Diagnostic, int[]> folded = new java.util.LinkedHashMap<>();
        for (Diagnostic d : run) {
            folded.computeIfAbsent(d, k -> new int[1])[0]++;
        }
        List<Diagnostic> all = new ArrayList<>(load.size() + folded.size());
        all.addAll(load);
        List<Diagnostic> runRows = new ArrayList<>();
        for (Diagnostic d : run) {
            // The first of each run of equal ones stands for all (identity tells run rows apart).
            int[] n = folded.get(d);
            if (n[0] > 0) {
                runRows.add(d);
                counts.put(d, n[0]);
                n[0] = 0;
            }
        }
        all.addAll(runRows);
        all.sort(BY_PLACE);
        shown = List.copyOf(all);
        repeats = new int[shown.size()];
        for (int i = 0; i < shown.size(); i++) {
            Diagnostic d = shown.get(i);
            Integer n = isRun(d) ? counts.get(d) : null;
            repeats[i] = n == null ? 1 : n;
        }
        counts.clear();
        table.setRedraw(false);
        table.clearAll();
        table.setItemCount(shown.size());
        table.setRedraw(true);
        changed.run();
    }

    /** The tooltip of a row: the whole message and where. */
    static String tip(Diagnostic d) {
        return ToolMsg.PROBLEMS_TIP.text(severity(d), location(d.pos()), d.message());
    }

    /** "error" or "warning" in the IDE's language (the command line's {@code FILE:LINE:COL: error:} keeps its English word). */
    private static String severity(Diagnostic d) {
        return (d.severity() == Severity.ERROR ? ToolMsg.PROBLEMS_ERROR : ToolMsg.PROBLEMS_WARNING).text();
    }

    /**
     * {@code FILE:LINE:COL} with the file's name only; the file alone for a diagnostic with no
     * line; a place that is not a file ({@code bus /dev/ttyUSB0}, {@code Robot humanoid}) whole.
     */
    public static String location(SourcePos p) {
        String f = p.file();
        if (p.line() <= 0 && f.contains(" ")) {
            return f;
        }
        String name = f.substring(Math.max(f.lastIndexOf('/'), f.lastIndexOf('\\')) + 1);
        return p.line() <= 0 ? name : name + ":" + p.line() + ":" + p.column();
    }

    /** The diagnostics shown, in table order: load and run diagnostics sorted by file, line, column. */
    public List<Diagnostic> shown() {
        return shown;
    }

    /** The run diagnostics shown. */
    public List<Diagnostic> runDiagnostics() {
        return run;
    }

    /** Number of errors shown. */
    public long errorCount() {
        return shown.stream().filter(d -> d.severity() == Severity.ERROR).count();
    }

    /** The text of a cell as the table shows it (tests). */
    public String cell(int row, int column) {
        return table.getItem(row).getText(column);
    }

    /** The title of a column (tests check the Location column is there). */
    public String columnTitle(int column) {
        return table.getColumn(column).getText();
    }
}
