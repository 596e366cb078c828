package org.parpe.gui.sweep;

import java.util.List;
import java.util.Locale;
import java.util.TreeMap;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Event;
import org.parpe.sim.sweep.SweepRow;

/**
 * The plot of a sweep or an optimisation, drawn with SWT's {@link GC}: for a sweep, the
 * objective of every run over one varied parameter (filled dots; hollow red ones for runs
 * whose robot fell over) with a line through the best run at each value; for an
 * optimisation, the convergence: every evaluation's objective (blue when it met the
 * constraints, orange when not) and the best acceptable objective so far in red, as the
 * command line's plots draw them. Which run may be the best is {@link Results#acceptable}'s rule,
 * the command line's.
 */
final class ResultsPlot {
    private static final Color BLUE = new Color(0x1F, 0x77, 0xB4);
    private static final Color RED = new Color(0xD6, 0x27, 0x28);
    private static final Color ORANGE = new Color(0xFF, 0x7F, 0x0E);
    private static final int LEFT = 64;
    private static final int RIGHT = 14;
    private static final int TOP = 24;
    private static final int BOTTOM = 44;

    private final Canvas canvas;
    private Results results;
    private String x;

    ResultsPlot(Composite parent) {
        canvas = new Canvas(parent, SWT.DOUBLE_BUFFERED | SWT.NO_BACKGROUND | SWT.BORDER);
        canvas.addListener(SWT.Paint, this::paint);
    }

    Canvas control() {
        return canvas;
    }

    /** Plots {@code r} over parameter {@code over} (ignored when optimising). */
    void show(Results r, String over) {
        results = r;
        x = over;
        redraw();
    }

    void redraw() {
        if (!canvas.isDisposed()) {
            canvas.redraw();
        }
    }

    /** The value on the horizontal axis for row {@code i}, or NaN when it has none. */
    private double xOf(SweepRow row, int i) {
        if (results.mode() == Results.Mode.OPTIMISE) {
            return i + 1;
        }
        Double v = row.values().get(x);
        return v == null ? Double.NaN : v;
    }

    private void paint(Event e) {
        GC gc = e.gc;
        Rectangle area = canvas.getClientArea();
        gc.setBackground(org.parpe.gui.panels.Theme.paper());
        gc.fillRectangle(area);
        gc.setForeground(org.parpe.gui.panels.Theme.ink());
        List<SweepRow> rows = results == null ? List.of() : results.rows();
        if (rows.isEmpty() || area.width < LEFT + RIGHT + 40 || area.height < TOP + BOTTOM + 40) {
            gc.drawText(results == null ? "Start a sweep or an optimisation to plot its objective here."
                    : "Waiting for the first run\u2026", 10, 10, true);
            return;
        }
        double[] box = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY};
        for (int i = 0; i < rows.size(); i++) {
            double xv = xOf(rows.get(i), i);
            double yv = results.objective().of(rows.get(i));
            if (Double.isFinite(xv) && Double.isFinite(yv)) {
                box[0] = Math.min(box[0], xv);
                box[1] = Math.max(box[1], xv);
                box[2] = Math.min(box[2], yv);
                box[3] = Math.max(box[3], yv);
            }
        }
        if (!(box[0] <= box[1])) {
            gc.drawText("No run has a measurement yet (see the error column).", 10, 10, true);
            return;
        }
        Axes a = new Axes(area, widen(box[0], box[1]), widen(box[2], box[3]));
        a.draw(gc, title(), legend(), results.mode() == Results.Mode.OPTIMISE ? "evaluation" : x);
        gc.setAntialias(SWT.ON);
        if (results.mode() == Results.Mode.OPTIMISE) {
            convergence(gc, a, rows);
        } else {
            scatter(gc, a, rows);
        }
    }

    private String title() {
        return results.objective().label() + (results.mode() == Results.Mode.OPTIMISE ? " per evaluation" : " over " + x);
    }

    private String legend() {
        return results.mode() == Results.Mode.OPTIMISE
                ? "blue: meets the constraints, orange: does not; red line: best so far"
                : "dots: runs (hollow red: fell over or failed, never the best); line: best at each value";
    }

    /** A range that is never empty: a single value gets a margin around it. */
    private static double[] widen(double lo, double hi) {
        if (hi > lo) {
            double pad = (hi - lo) * 0.05;
            return new double[] {lo - pad, hi + pad};
        }
        double pad = lo == 0 ? 1 : Math.abs(lo) * 0.1;
        return new double[] {lo - pad, hi + pad};
    }

    private void scatter(GC gc, Axes a, List<SweepRow> rows) {
        TreeMap<Double, Double> best = new TreeMap<>();
        for (int i = 0; i < rows.size(); i++) {
            SweepRow r = rows.get(i);
            double xv = xOf(r, i);
            double yv = results.objective().of(r);
            if (!Double.isFinite(xv) || !Double.isFinite(yv)) {
                continue;
            }
            if (results.acceptable(r)) {
                best.merge(xv, yv, Math::max);
            }
            dot(gc, a.px(xv), a.py(yv), r.fell() || !r.ok() ? RED : BLUE, !r.fell() && r.ok());
        }
        gc.setForeground(BLUE);
        gc.setLineWidth(2);
        int[] last = null;
        for (var en : best.entrySet()) {
            int[] p = {a.px(en.getKey()), a.py(en.getValue())};
            if (last != null) {
                gc.drawLine(last[0], last[1], p[0], p[1]);
            }
            last = p;
        }
        gc.setLineWidth(1);
    }

    private void convergence(GC gc, Axes a, List<SweepRow> rows) {
        double bestSoFar = Double.NaN;
        int[] last = null;
        for (int i = 0; i < rows.size(); i++) {
            SweepRow r = rows.get(i);
            double yv = results.objective().of(r);
            if (Double.isFinite(yv)) {
                dot(gc, a.px(i + 1), a.py(yv), results.acceptable(r) ? BLUE : ORANGE, true);
            }
            if (results.acceptable(r) && (Double.isNaN(bestSoFar) || yv > bestSoFar)) {
                bestSoFar = yv;
            }
            if (!Double.isNaN(bestSoFar)) {
                int[] p = {a.px(i + 1), a.py(bestSoFar)};
                gc.setForeground(RED);
                gc.setLineWidth(2);
                if (last != null) {
                    gc.drawLine(last[0], last[1], p[0], last[1]);
                    gc.drawLine(p[0], last[1], p[0], p[1]);
                }
                gc.setLineWidth(1);
                last = p;
            }
        }
    }

    private static void dot(GC gc, int px, int py, Color c, boolean filled) {
        if (filled) {
            gc.setBackground(c);
            gc.fillOval(px - 3, py - 3, 7, 7);
        } else {
            gc.setForeground(c);
            gc.drawOval(px - 3, py - 3, 6, 6);
        }
    }

    /** The frame of the plot: data ranges mapped to pixels, gridlines and labels. */
    private record Axes(Rectangle area, double[] xr, double[] yr) {
        int px(double v) {
            return LEFT + (int) Math.round((v - xr[0]) / (xr[1] - xr[0]) * (area.width - LEFT - RIGHT));
        }

        int py(double v) {
            return area.height - BOTTOM - (int) Math.round((v - yr[0]) / (yr[1] - yr[0]) * (area.height - TOP - BOTTOM));
        }

        void draw(GC gc, String title, String legend, String xLabel) {
            int bottom = area.height - BOTTOM;
            int right = area.width - RIGHT;
            gc.setForeground(org.parpe.gui.panels.Theme.faint());
            for (double v : ticks(yr[0], yr[1])) {
                gc.drawLine(LEFT, py(v), right, py(v));
                String s = label(v);
                gc.drawText(s, LEFT - 6 - gc.textExtent(s).x, py(v) - gc.textExtent(s).y / 2, true);
            }
            for (double v : ticks(xr[0], xr[1])) {
                gc.drawLine(px(v), bottom, px(v), bottom + 4);
                String s = label(v);
                gc.drawText(s, px(v) - gc.textExtent(s).x / 2, bottom + 5, true);
            }
            gc.drawRectangle(LEFT, TOP, right - LEFT, bottom - TOP);
            gc.setForeground(org.parpe.gui.panels.Theme.ink());
            gc.drawText(title, LEFT, 4, true);
            gc.drawText(legend, 4, area.height - gc.textExtent(legend).y - 2, true);
            gc.drawText(xLabel, right - gc.textExtent(xLabel).x, area.height - gc.textExtent(xLabel).y - 2, true);
        }

        /** About five round values within {@code [lo, hi]}. */
        static double[] ticks(double lo, double hi) {
            double raw = (hi - lo) / 5;
            double mag = Math.pow(10, Math.floor(Math.log10(raw)));
            double step = raw / mag < 2 ? mag : raw / mag < 5 ? 2 * mag : 5 * mag;
            double first = Math.ceil(lo / step) * step;
            int n = (int) Math.floor((hi - first) / step) + 1;
            double[] out = new double[Math.max(0, Math.min(n, 20))];
            for (int i = 0; i < out.length; i++) {
                out[i] = first + i * step;
            }
            return out;
        }

        static String label(double v) {
            String s = String.format(Locale.ROOT, "%.4g", Math.abs(v) < 1e-12 ? 0 : v);
            return s.contains("e") || !s.contains(".") ? s : s.replaceAll("0+$", "").replaceAll("\\.$", "");
        }
    }
}
