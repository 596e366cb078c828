package org.parpe.gui.sweep;

import java.util.List;
import java.util.TreeMap;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Composite;
import org.parpe.core.plot.PlotStyle;
import org.parpe.gui.panels.ChartView;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.sweep.SweepRow;

/**
 * The plot of a sweep or an optimisation in the IDE's one {@link ChartView}: for a sweep, the
 * objective of every run over one varied parameter (grey dots; hollow red rings for runs whose
 * robot fell over or failed, never the best) with a line through the best run at each value; for
 * an optimisation, the convergence: every evaluation's objective (grey when it met the
 * constraints, orange when not) and the best acceptable objective so far, as the command line's
 * plots draw them, in the one {@link PlotStyle}. Which run may be the best is
 * {@link Results#acceptable}'s rule, the command line's.
 */
final class ResultsPlot {
    static final ToolMsg RUNS = ToolMsg.SWEEP_SERIES_RUNS;
    static final ToolMsg FELL = ToolMsg.SWEEP_SERIES_FELL;
    static final ToolMsg BEST = ToolMsg.SWEEP_SERIES_BEST;
    static final ToolMsg MISSES = ToolMsg.SWEEP_SERIES_MISSES;
    static final ToolMsg BEST_SO_FAR = ToolMsg.SWEEP_SERIES_BEST_SO_FAR;

    private final ChartView chart;
    private Results results;
    private String x;

    ResultsPlot(Composite parent) {
        chart = new ChartView(parent, SWT.BORDER);
        redraw();
    }

    Canvas control() {
        return chart.control();
    }

    /** The chart (for tests). */
    ChartView chart() {
        return chart;
    }

    /** Plots {@code r} over parameter {@code over} (ignored when optimising). */
    void show(Results r, String over) {
        results = r;
        x = over;
        redraw();
    }

    void redraw() {
        if (chart.control().isDisposed()) {
            return;
        }
        List<SweepRow> rows = results == null ? List.of() : results.rows();
        if (rows.isEmpty()) {
            chart.message(results == null ? ToolMsg.SWEEP_PLOT_EMPTY.text() : ToolMsg.SWEEP_PLOT_WAITING.text());
            return;
        }
        int n = rows.size();
        double[] xs = new double[n];
        double[] ys = new double[n];
        for (int i = 0; i < n; i++) {
            xs[i] = xOf(rows.get(i), i);
            ys[i] = results.objective().of(rows.get(i));
        }
        double[] xr = range(xs, ys);
        double[] yr = range(ys, xs);
        if (!(xr[0] <= xr[1])) {
            chart.message(ToolMsg.SWEEP_PLOT_NO_MEASUREMENT.text());
            return;
        }
        boolean optimise = results.mode() == Results.Mode.OPTIMISE;
        String title = optimise ? ToolMsg.SWEEP_PLOT_PER_EVALUATION.text(RunSettings.label(results.objective()))
                : ToolMsg.SWEEP_PLOT_OVER_X.text(RunSettings.label(results.objective()), x);
        chart.show(title, optimise ? ToolMsg.SWEEP_EVALUATION.text() : x, pad(xr), pad(yr), f -> {
            if (optimise) {
                convergence(f, rows, xs, ys);
            } else {
                scatter(f, rows, xs, ys);
            }
        });
    }

    /** The value on the horizontal axis for row {@code i}, or NaN when it has none. */
    private double xOf(SweepRow row, int i) {
        if (results.mode() == Results.Mode.OPTIMISE) {
            return i + 1;
        }
        Double v = row.values().get(x);
        return v == null ? Double.NaN : v;
    }

    /** The range of the finite {@code v} whose partner in {@code other} is finite too ({lo, hi}; lo > hi when none). */
    private static double[] range(double[] v, double[] other) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < v.length; i++) {
            if (Double.isFinite(v[i]) && Double.isFinite(other[i])) {
                lo = Math.min(lo, v[i]);
                hi = Math.max(hi, v[i]);
            }
        }
        return new double[] {lo, hi};
    }

    private static double[] pad(double[] r) {
        double m = (r[1] - r[0]) * 0.05;
        return new double[] {r[0] - m, r[1] + m};
    }

    private void scatter(ChartView.Frame f, List<SweepRow> rows, double[] xs, double[] ys) {
        int n = rows.size();
        double[] upY = new double[n];
        double[] downY = new double[n];
        TreeMap<Double, Double> best = new TreeMap<>();
        for (int i = 0; i < n; i++) {
            SweepRow r = rows.get(i);
            boolean apart = r.fell() || !r.ok();
            upY[i] = apart ? Double.NaN : ys[i];
            downY[i] = apart ? ys[i] : Double.NaN;
            if (Double.isFinite(xs[i]) && Double.isFinite(ys[i]) && results.acceptable(r)) {
                best.merge(xs[i], ys[i], Math::max);
            }
        }
        f.points(RUNS.text(), xs, upY, n, PlotStyle.OTHER_RUN, false);
        f.points(FELL.text(), xs, downY, n, PlotStyle.FELL, true);
        double[] bx = best.keySet().stream().mapToDouble(Double::doubleValue).toArray();
        double[] by = best.values().stream().mapToDouble(Double::doubleValue).toArray();
        if (bx.length > 0) {
            f.line(BEST.text(), bx, by, bx.length, PlotStyle.BEST, false);
        }
    }

    private void convergence(ChartView.Frame f, List<SweepRow> rows, double[] xs, double[] ys) {
        int n = rows.size();
        double[] ok = new double[n];
        double[] misses = new double[n];
        double[] bestSoFar = new double[n];
        double best = Double.NaN;
        for (int i = 0; i < n; i++) {
            boolean acceptable = results.acceptable(rows.get(i));
            ok[i] = acceptable ? ys[i] : Double.NaN;
            misses[i] = acceptable ? Double.NaN : ys[i];
            if (acceptable && Double.isFinite(ys[i]) && (Double.isNaN(best) || ys[i] > best)) {
                best = ys[i];
            }
            bestSoFar[i] = best;
        }
        f.points(RUNS.text(), xs, ok, n, PlotStyle.OTHER_RUN, false);
        f.points(MISSES.text(), xs, misses, n, PlotStyle.MISSES, false);
        f.line(BEST_SO_FAR.text(), xs, bestSoFar, n, PlotStyle.BEST_SO_FAR, false);
    }
}
