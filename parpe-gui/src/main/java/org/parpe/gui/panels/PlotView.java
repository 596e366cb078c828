package org.parpe.gui.panels;

import java.util.Arrays;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.List;
import org.parpe.gui.run.AngleRecorder;

/**
 * Live plots of commanded (solid) and measured (dashed) joint angles over the last seconds of
 * simulated time, for the modules chosen in the list beside the chart.
 */
public final class PlotView {
    private static final double WINDOW = 10.0;
    private static final int[] PALETTE = {0x1F77B4, 0xD62728, 0x2CA02C, 0xFF7F0E, 0x9467BD, 0x17BECF, 0x8C564B, 0xE377C2};

    private final SashForm sash;
    private final List chooser;
    private final Canvas chart;
    private final double[] t = new double[AngleRecorder.capacity()];
    private final double[] cmd = new double[AngleRecorder.capacity()];
    private final double[] meas = new double[AngleRecorder.capacity()];
    private final Color[] colors = new Color[PALETTE.length];
    private AngleRecorder recorder;
    private int[] ids = new int[0];

    public PlotView(Composite parent) {
        sash = new SashForm(parent, SWT.HORIZONTAL);
        chooser = new List(sash, SWT.MULTI | SWT.V_SCROLL | SWT.BORDER);
        chooser.setToolTipText("Modules to plot: m3 is module 3 (Ctrl+click for several)");
        chooser.addListener(SWT.Selection, e -> refresh());
        chart = new Canvas(sash, SWT.DOUBLE_BUFFERED | SWT.NO_BACKGROUND);
        chart.addListener(SWT.Paint, this::paint);
        sash.setWeights(1, 6);
        for (int i = 0; i < PALETTE.length; i++) {
            colors[i] = new Color((PALETTE[i] >> 16) & 0xFF, (PALETTE[i] >> 8) & 0xFF, PALETTE[i] & 0xFF);
        }
    }

    /** The top-level control. */
    public Control control() {
        return sash;
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
        chart.redraw();
    }

    /** Plots what {@code r} records (null: nothing). */
    public void setRecorder(AngleRecorder r) {
        recorder = r;
        chart.redraw();
    }

    /** Redraws with the latest samples. */
    public void refresh() {
        if (!chart.isDisposed() && chart.isVisible()) {
            chart.redraw();
        }
    }

    private void paint(Event e) {
        GC gc = e.gc;
        Rectangle r = chart.getClientArea();
        gc.setBackground(org.parpe.gui.panels.Theme.paper());
        gc.fillRectangle(r);
        int left = 44, right = r.width - 10, top = 10, bottom = r.height - 22;
        if (right - left < 20 || bottom - top < 20) {
            return;
        }
        int[] sel = chooser.getSelectionIndices();
        double tEnd = WINDOW;
        double lo = -90, hi = 90;
        if (recorder != null) {
            for (int s : sel) {
                int n = recorder.copy(ids[s], t, cmd, meas);
                if (n > 0) {
                    tEnd = Math.max(tEnd, t[n - 1]);
                }
            }
        }
        Frame f = new Frame(left, right, top, bottom, tEnd - WINDOW, tEnd, lo, hi);
        axes(gc, f);
        gc.setAntialias(SWT.ON);
        gc.setLineWidth(2);
        for (int k = 0; recorder != null && k < sel.length; k++) {
            int n = recorder.copy(ids[sel[k]], t, cmd, meas);
            gc.setForeground(colors[k % colors.length]);
            gc.setLineStyle(SWT.LINE_SOLID);
            series(gc, f, cmd, n);
            gc.setLineStyle(SWT.LINE_DOT);
            series(gc, f, meas, n);
            gc.setLineStyle(SWT.LINE_SOLID);
            gc.drawText("m" + ids[sel[k]], left + 8 + 48 * k, top + 2, true);
        }
        gc.setLineWidth(1);
        gc.setForeground(org.parpe.gui.panels.Theme.ink());
        String legend = recorder == null ? "Run a script to see joint angles" : "solid: commanded, dotted: measured (\u00b0)";
        gc.drawText(legend, right - gc.textExtent(legend).x - 4, bottom - gc.textExtent(legend).y - 2, true);
    }

    private record Frame(int left, int right, int top, int bottom, double t0, double t1, double lo, double hi) {
        int x(double time) {
            return left + (int) Math.round((time - t0) / (t1 - t0) * (right - left));
        }

        int y(double v) {
            double c = Math.max(lo, Math.min(hi, v));
            return bottom - (int) Math.round((c - lo) / (hi - lo) * (bottom - top));
        }
    }

    private void axes(GC gc, Frame f) {
        gc.setForeground(org.parpe.gui.panels.Theme.faint());
        for (int v = -90; v <= 90; v += 45) {
            gc.drawLine(f.left, f.y(v), f.right, f.y(v));
            gc.drawText(Integer.toString(v), 4, f.y(v) - 8, true);
        }
        for (double s = Math.ceil(f.t0); s <= f.t1; s += 2) {
            if (s >= 0) {
                gc.drawLine(f.x(s), f.bottom, f.x(s), f.bottom + 4);
                gc.drawText(String.format("%.0f s", s), f.x(s) - 8, f.bottom + 5, true);
            }
        }
        gc.drawRectangle(f.left, f.top, f.right - f.left, f.bottom - f.top);
    }

    private void series(GC gc, Frame f, double[] v, int n) {
        int px = Integer.MIN_VALUE, py = 0;
        for (int i = 0; i < n; i++) {
            if (t[i] < f.t0 || !Double.isFinite(v[i])) {
                px = Integer.MIN_VALUE;
                continue;
            }
            int x = f.x(t[i]);
            int y = f.y(v[i]);
            if (px != Integer.MIN_VALUE) {
                gc.drawLine(px, py, x, y);
            }
            px = x;
            py = y;
        }
    }
}
