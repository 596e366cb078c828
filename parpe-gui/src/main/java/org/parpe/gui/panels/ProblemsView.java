package org.parpe.gui.panels;

import java.util.List;
import java.util.function.Consumer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.eclipse.swt.widgets.TableItem;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;

/**
 * The Problems view: one row per error or warning of the last validation, or per problem of the
 * last run. Selecting a row (click, Enter, double-click) jumps to its place in the editor.
 */
public final class ProblemsView {
    private final Table table;
    private List<Diagnostic> shown = List.of();

    /** Creates the view; {@code jump} receives the diagnostic the user picked. */
    public ProblemsView(Composite parent, Consumer<Diagnostic> jump) {
        Composite box = new Composite(parent, SWT.NONE);
        box.setLayout(new FillLayout());
        table = new Table(box, SWT.FULL_SELECTION | SWT.SINGLE | SWT.V_SCROLL);
        table.setHeaderVisible(true);
        table.setLinesVisible(true);
        column("", 90);
        column("Description", 640);
        column("Location", 200);
        table.addListener(SWT.Selection, e -> pick(jump));
        table.addListener(SWT.DefaultSelection, e -> pick(jump));
    }

    private void column(String name, int width) {
        TableColumn c = new TableColumn(table, SWT.LEFT);
        c.setText(name);
        c.setWidth(width);
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

    /** Shows {@code diagnostics}. */
    public void show(List<Diagnostic> diagnostics) {
        shown = List.copyOf(diagnostics);
        table.setRedraw(false);
        table.removeAll();
        for (Diagnostic d : shown) {
            TableItem it = new TableItem(table, SWT.NONE);
            boolean err = d.severity() == Severity.ERROR;
            it.setImage(0, err ? Icons.of(table.getDisplay()).error : Icons.of(table.getDisplay()).warning);
            it.setText(0, err ? "error" : "warning");
            it.setForeground(0, table.getDisplay().getSystemColor(err ? SWT.COLOR_RED : SWT.COLOR_DARK_YELLOW));
            it.setText(1, d.message());
            it.setText(2, location(d));
        }
        table.setRedraw(true);
    }

    private static String location(Diagnostic d) {
        String f = d.pos().file();
        int slash = Math.max(f.lastIndexOf('/'), f.lastIndexOf('\\'));
        return f.substring(slash + 1) + ":" + d.pos().line() + ":" + d.pos().column();
    }

    /** The diagnostics shown. */
    public List<Diagnostic> shown() {
        return shown;
    }

    /** Number of errors shown. */
    public long errorCount() {
        return shown.stream().filter(d -> d.severity() == Severity.ERROR).count();
    }
}
