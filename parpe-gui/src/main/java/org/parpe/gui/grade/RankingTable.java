package org.parpe.gui.grade;

import org.parpe.gui.text.UiMsg;
import java.util.List;
import java.util.Locale;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableItem;
import org.parpe.gui.panels.TitleWidths;
import org.parpe.sim.grade.Outcome;
import org.parpe.sim.grade.Row;

/**
 * The ranking: one line per student in report order, the columns of {@code report.csv} (rank,
 * student, score, parts, forward, distance, fell, time, problem: its first line; the whole of it
 * as the line's tool tip is the Problem box's).
 */
final class RankingTable {
    /** The columns' titles, in the IDE's language. */
    static String[] titles() {
        return new String[] {UiMsg.CLASS_COL_RANK.text(), UiMsg.CLASS_COL_STUDENT.text(), UiMsg.CLASS_COL_SCORE.text(),
            UiMsg.CLASS_COL_PARTS.text(), UiMsg.CLASS_COL_FORWARD.text(), UiMsg.CLASS_COL_DISTANCE.text(),
            UiMsg.CLASS_COL_FELL.text(), UiMsg.CLASS_COL_TIME.text(), UiMsg.CLASS_COL_PROBLEM.text()};
    }
    private static final int[] WIDTHS = {50, 180, 70, 240, 105, 110, 45, 75, 420};
    private final Table table;
    private List<Row> rows = List.of();

    RankingTable(Composite parent) {
        table = new Table(parent, SWT.BORDER | SWT.FULL_SELECTION | SWT.SINGLE | SWT.V_SCROLL | SWT.H_SCROLL);
        table.setHeaderVisible(true);
        table.setLinesVisible(true);
        String[] titles = titles();
        for (int i = 0; i < titles.length; i++) {
            TitleWidths.column(table, i == 0 || (i >= 2 && i != 3 && i != 6 && i != 8) ? SWT.RIGHT : SWT.LEFT,
                    titles[i], WIDTHS[i]);
        }
    }

    Table control() {
        return table;
    }

    /** Shows {@code ranked} (in report order). */
    void show(List<Row> ranked) {
        rows = List.copyOf(ranked);
        table.removeAll();
        for (Row r : rows) {
            TableItem item = new TableItem(table, SWT.NONE);
            item.setText(cells(r));
            if (r.rank() == 0) {
                item.setForeground(table.getDisplay().getSystemColor(SWT.COLOR_DARK_RED)); // the theme's own background stays
            }
        }
    }

    /** The row of the selected line, or null. */
    Row selected() {
        int i = table.getSelectionIndex();
        return i < 0 || i >= rows.size() ? null : rows.get(i);
    }

    /** The rows shown, in report order. */
    List<Row> rows() {
        return rows;
    }

    /** The texts of {@code r}'s cells: the report's numbers, with the report's decimals. */
    static String[] cells(Row r) {
        Outcome o = r.outcome();
        String name = r.student().name().replaceAll("\\p{Cntrl}", "?");
        String problem = o.reason().lines().findFirst().orElse("");
        if (!o.ranked()) {
            return new String[] {"-", name, "", "", "", "", "", "", problem};
        }
        return new String[] {Integer.toString(r.rank()), name, String.format(Locale.ROOT, "%.1f", o.score()), o.parts(),
            String.format(Locale.ROOT, "%.3f", o.dx()), String.format(Locale.ROOT, "%.3f", o.distance()),
            (o.fell() ? UiMsg.CLASS_YES : UiMsg.CLASS_NO).text(), String.format(Locale.ROOT, "%.2f", o.time()), problem};
    }
}
