package org.parpe.gui.sweep;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Locale;
import java.util.function.Function;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.eclipse.swt.widgets.TableItem;
import org.parpe.core.lang.Numbers;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.sweep.SweepRow;

/**
 * The results table: one row per run, a column per varied parameter and per measurement.
 * Virtual (a sweep may have many thousand runs) and sortable: a click on a column header sorts
 * by it, a second click reverses. Rows arriving during a run keep the chosen order.
 */
final class ResultsTable {
    private final Table table;
    private final List<Column> columns = new ArrayList<>();
    private List<SweepRow> view = new ArrayList<>();
    private final Map<SweepRow, Integer> place = new IdentityHashMap<>();
    private Results results;
    private Column sortedBy;
    private boolean descending;

    /** One column: its header, its text and its sort key. */
    private record Column(String title, Function<SweepRow, String> text, Comparator<SweepRow> order) {
    }

    ResultsTable(Composite parent) {
        table = new Table(parent, SWT.VIRTUAL | SWT.BORDER | SWT.FULL_SELECTION | SWT.V_SCROLL | SWT.H_SCROLL);
        table.setHeaderVisible(true);
        table.setLinesVisible(true);
        table.addListener(SWT.SetData, this::fill);
    }

    Table control() {
        return table;
    }

    /** Shows the rows of {@code r} (empty at first), with columns for its parameters. */
    void show(Results r) {
        results = r;
        for (TableColumn c : table.getColumns()) {
            c.dispose();
        }
        columns.clear();
        sortedBy = null;
        table.setSortColumn(null);
        // The run's place in the engine's order, from 0 as the CSV's and parpe sweep's run column: a
        // sweep's run number, an optimisation's evaluation number (the point's own index restarts
        // with each independent search).
        columns.add(new Column(ToolMsg.SWEEP_COL_RUN.text(), row -> Integer.toString(place.get(row)), Comparator.comparingInt(place::get)));
        for (String p : r.parameters()) {
            columns.add(new Column(p, row -> value(row.values().get(p)),
                    Comparator.comparingDouble(row -> nanLast(row.values().get(p)))));
        }
        measure(ToolMsg.SWEEP_COL_FORWARD_SPEED.text(), SweepRow::forwardSpeed);
        measure(ToolMsg.SWEEP_COL_SPEED.text(), SweepRow::speed);
        measure(ToolMsg.SWEEP_COL_FORWARD.text(), SweepRow::forward);
        measure(ToolMsg.SWEEP_COL_DISTANCE.text(), SweepRow::distance);
        measure(ToolMsg.SWEEP_COL_MAX_TILT.text(), SweepRow::maxTiltDeg);
        measure(ToolMsg.SWEEP_COL_JOINT_TRAVEL.text(), SweepRow::jointTravelDeg);
        if (r.scored()) {
            measure(ToolMsg.SWEEP_COL_SCORE.text(), SweepRow::score);
        }
        columns.add(new Column(ToolMsg.SWEEP_COL_FELL.text(), row -> (row.fell() ? ToolMsg.SWEEP_YES : ToolMsg.SWEEP_NO).text(), Comparator.comparing(SweepRow::fell)));
        columns.add(new Column(ToolMsg.SWEEP_COL_ERROR.text(), row -> row.error().toString(),
                Comparator.comparing(row -> row.error().toString())));
        for (int i = 0; i < columns.size(); i++) {
            Column c = columns.get(i);
            boolean text = i >= columns.size() - 2;
            TableColumn tc = new TableColumn(table, text ? SWT.LEFT : SWT.RIGHT);
            tc.setText(c.title());
            tc.setWidth(i == columns.size() - 1 ? 300 : i == 0 ? 50 : text ? 50 : i <= r.parameters().size() ? 80 : 140);
            tc.setMoveable(true);
            tc.addListener(SWT.Selection, e -> sort(c, tc));
        }
        refresh();
    }

    private void measure(String title, Function<SweepRow, Double> m) {
        columns.add(new Column(title, row -> number(m.apply(row)), Comparator.comparingDouble(row -> nanLast(m.apply(row)))));
    }

    private static String value(Double v) {
        return v == null || Double.isNaN(v) ? "" : Numbers.format(v);
    }

    /** A measurement as the table shows it: four decimals, empty when the run did not start. */
    static String number(double v) {
        return Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.4f", v);
    }

    private static double nanLast(Double v) {
        return v == null || Double.isNaN(v) ? Double.NEGATIVE_INFINITY : v;
    }

    private void sort(Column c, TableColumn tc) {
        descending = c == sortedBy ? !descending : c != columns.get(0);
        sortedBy = c;
        table.setSortColumn(tc);
        table.setSortDirection(descending ? SWT.DOWN : SWT.UP);
        refresh();
    }

    /** Shows the rows now in the results (after rows arrived or the order changed). */
    void refresh() {
        List<SweepRow> rows = new ArrayList<>(results == null ? List.of() : results.rows());
        place.clear();
        for (int i = 0; i < rows.size(); i++) {
            place.put(rows.get(i), i);
        }
        if (sortedBy != null) {
            Comparator<SweepRow> order = descending ? sortedBy.order().reversed() : sortedBy.order();
            // Ties keep the engine's order, whichever the direction.
            rows.sort(order.thenComparing(columns.get(0).order()));
        }
        view = rows;
        table.setItemCount(rows.size());
        table.clearAll();
    }

    private void fill(Event e) {
        TableItem item = (TableItem) e.item;
        int i = e.index;
        if (i < 0 || i >= view.size()) {
            return;
        }
        SweepRow row = view.get(i);
        for (int c = 0; c < columns.size(); c++) {
            item.setText(c, columns.get(c).text().apply(row));
        }
    }

    /** The text of cell ({@code row}, {@code column}) as shown (tests, screenshots). */
    String cell(int row, int column) {
        return table.getItem(row).getText(column);
    }

    /** The run shown on line {@code i}. */
    SweepRow rowAt(int i) {
        return view.get(i);
    }
}
