package org.parpe.gui.sweep;

import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.parpe.gui.text.ToolMsg;

/** The results table beside the plot, with the choice of the parameter the plot runs over. */
final class ResultsPane {
    private final SashForm split;
    private final ResultsTable table;
    private final ResultsPlot plot;
    private final Combo over;
    private Results results;

    ResultsPane(Composite parent) {
        split = new SashForm(parent, SWT.HORIZONTAL);
        split.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        table = new ResultsTable(split);
        Composite right = new Composite(split, SWT.NONE);
        right.setLayout(new GridLayout(2, false));
        plot = new ResultsPlot(right);
        plot.control().setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true, 2, 1));
        new Label(right, SWT.NONE).setText(ToolMsg.SWEEP_PLOT_OVER.text());
        over = new Combo(right, SWT.READ_ONLY);
        over.setLayoutData(new GridData(160, SWT.DEFAULT));
        over.setToolTipText(ToolMsg.SWEEP_PLOT_OVER_TIP.text());
        over.addListener(SWT.Selection, e -> plot.show(results, over.getText()));
        split.setWeights(55, 45);
    }

    /** Shows {@code r} (empty at first): the table's columns, the plot over its first parameter. */
    void show(Results r) {
        results = r;
        table.show(r);
        over.setItems(r.parameters().toArray(new String[0]));
        over.select(0);
        over.setEnabled(r.mode() == Results.Mode.SWEEP);
        plot.show(r, over.getText());
    }

    /** Shows the rows now in the results. */
    void refresh() {
        table.refresh();
        plot.redraw();
    }

    ResultsTable table() {
        return table;
    }
}
