package org.parpe.gui.panels;

import java.util.Arrays;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.List;
import org.parpe.core.plot.AngleRecorder;
import org.parpe.core.plot.PlotStyle;
import org.parpe.gui.text.ToolMsg;

/**
 * Live plots of commanded (dashed) and measured (solid) joint angles over the last seconds of
 * simulated time, for the modules chosen in the list beside the chart, in the IDE's one
 * {@link ChartView}.
 */
public final class PlotView {
    /** Seconds of run time shown. */
    private static final double WINDOW = 10.0;
    /** How many samples the recorder keeps, and how far apart (seconds of run time). */
    private static final int CAPACITY = 4096;
    private static final double INTERVAL = 0.02;

    private final SashForm sash;
    private final List chooser;
    private final ChartView chart;
    private final double[] t = new double[CAPACITY];
    private final double[] cmd = new double[CAPACITY];
    private final double[] meas = new double[CAPACITY];
    private AngleRecorder recorder;
    private int[] ids = new int[0];

    public PlotView(Composite parent) {
        sash = new SashForm(parent, SWT.HORIZONTAL);
        chooser = new List(sash, SWT.MULTI | SWT.V_SCROLL | SWT.BORDER);
        chooser.setToolTipText(ToolMsg.PLOT_CHOOSER_TIP.text());
        chooser.addListener(SWT.Selection, e -> refresh());
        chart = new ChartView(sash, SWT.NONE);
        sash.setWeights(1, 6);
        refresh();
    }

    /** The top-level control. */
    public Control control() {
        return sash;
    }

    /** The chart (for tests). */
    public ChartView chart() {
        return chart;
    }

    /** A recorder of the size this view plots, for the next run. */
    public static AngleRecorder newRecorder() {
        return AngleRecorder.latest(CAPACITY, INTERVAL);
    }

    /** Lists the modules of the program; keeps the choice when the set is the same. */
    public void setModules(int[] moduleIds) {
        if (Arrays.equals(ids, moduleIds)) {
            return;
        }
        ids = moduleIds.clone();
        chooser.removeAll();
        for (int id : ids) {
            // As the chart's legend names them: short enough to be read in a narrow list.
            chooser.add("m" + id);
        }
        chooser.setSelection(0, Math.min(2, ids.length - 1));
        refresh();
    }

    /** Plots what {@code r} records (null: nothing). */
    public void setRecorder(AngleRecorder r) {
        recorder = r;
        refresh();
    }

    /** Redraws with the latest samples. */
    public void refresh() {
        if (chart.control().isDisposed() || !chart.control().isVisible() && recorder != null) {
            return;
        }
        if (recorder == null) {
            chart.message(ToolMsg.PLOT_EMPTY.text());
            return;
        }
        int[] sel = chooser.getSelectionIndices();
        double tEnd = WINDOW;
        for (int s : sel) {
            int n = recorder.copy(ids[s], t, cmd, meas);
            if (n > 0) {
                tEnd = Math.max(tEnd, t[n - 1]);
            }
        }
        chart.show(ToolMsg.PLOT_TITLE.text(), ToolMsg.PLOT_TIME_AXIS.text(), new double[] {tEnd - WINDOW, tEnd}, new double[] {-90, 90}, f -> {
            for (int k = 0; k < sel.length; k++) {
                int id = ids[sel[k]];
                int n = recorder.copy(id, t, cmd, meas);
                int rgb = PlotStyle.series(k);
                f.line(ToolMsg.PLOT_MEASURED.text(id), t, meas, n, rgb, false);
                f.line(ToolMsg.PLOT_COMMANDED.text(id), t, cmd, n, rgb, true);
            }
        });
    }
}
