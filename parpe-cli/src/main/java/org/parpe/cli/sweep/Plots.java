package org.parpe.cli.sweep;

import org.parpe.cli.text.CliMsg;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Predicate;
import org.knowm.xchart.XYChart;
import org.parpe.cli.plot.PngCharts;
import org.parpe.core.plot.PlotStyle;
import org.parpe.sim.sweep.Axis;
import org.parpe.sim.sweep.Evaluation;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.OptimizationResult;
import org.parpe.sim.sweep.SweepResult;
import org.parpe.sim.sweep.SweepRow;

/**
 * The PNG plots of the sweep commands, by XChart ({@link PngCharts}): the objective over each
 * varied parameter (every run a grey dot, a run whose robot fell over a hollow red ring, the best
 * run at each value joined by a line, under the same rule as the summary's best), and an
 * optimisation's convergence (every evaluation a dot, the best so far a line).
 */
final class Plots {
    static final CliMsg RUNS = CliMsg.PLOT_EACH_RUN;
    static final CliMsg FELL = CliMsg.PLOT_FELL;
    static final CliMsg FELL_NEVER_BEST = CliMsg.PLOT_FELL_NEVER_BEST;
    static final CliMsg BEST = CliMsg.PLOT_BEST_AT_VALUE;
    private static final int WIDTH = 1000;
    /** A panel's height: its plot, axis titles and a legend of up to three rows. */
    private static final int PANEL = 370;

    private Plots() {
    }

    /** One panel per axis: {@code objective} of every run over the axis's values. */
    static void sweep(OutputStream out, String title, List<Axis> axes, List<SweepRow> rows, Objective objective,
                      boolean countFallen) throws IOException {
        PngCharts.write(sweepPanels(title, axes, rows, objective, countFallen), out);
    }

    static List<XYChart> sweepPanels(String title, List<Axis> axes, List<SweepRow> rows, Objective objective,
                                     boolean countFallen) {
        Predicate<SweepRow> rule = SweepResult.rule(countFallen);
        double[] scores = rows.stream().mapToDouble(r -> r.ok() ? objective.of(r) : Double.NaN).toArray();
        List<XYChart> panels = new ArrayList<>();
        for (int a = 0; a < axes.size(); a++) {
            String name = axes.get(a).name();
            double[] xs = rows.stream().mapToDouble(r -> r.values().get(name)).toArray();
            XYChart c = PngCharts.panel(WIDTH, PANEL, a == 0 ? title : "", name, objective.label());
            double[] upX = xs.clone();
            double[] upY = scores.clone();
            double[] fellX = xs.clone();
            double[] fellY = scores.clone();
            Map<Double, Double> best = new TreeMap<>();
            for (int i = 0; i < xs.length; i++) {
                if (rows.get(i).fell()) {
                    upY[i] = Double.NaN;
                } else {
                    fellY[i] = Double.NaN;
                }
                if (SweepResult.contender(rows.get(i), objective, rule)) {
                    best.merge(xs[i], scores[i], Math::max);
                }
            }
            PngCharts.points(c, RUNS.text(), upX, upY, PlotStyle.OTHER_RUN, false);
            PngCharts.points(c, (countFallen ? FELL : FELL_NEVER_BEST).text(), fellX, fellY, PlotStyle.FELL, true);
            double[] bx = best.keySet().stream().mapToDouble(Double::doubleValue).toArray();
            double[] by = best.values().stream().mapToDouble(Double::doubleValue).toArray();
            if (bx.length > 0) {
                PngCharts.line(c, BEST.text(), bx, by, bx.length, PlotStyle.BEST);
            }
            panels.add(c);
        }
        return panels;
    }

    /** Every evaluation's score and the best feasible score so far, over the evaluations. */
    static void convergence(OutputStream out, String title, OptimizationResult result) throws IOException {
        PngCharts.write(List.of(convergencePanel(title, result)), out);
    }

    static XYChart convergencePanel(String title, OptimizationResult result) {
        List<Evaluation> all = result.evaluations();
        double[] n = new double[all.size()];
        double[] feasible = new double[all.size()];
        double[] misses = new double[all.size()];
        for (int i = 0; i < n.length; i++) {
            n[i] = i + 1;
            feasible[i] = all.get(i).feasible() ? all.get(i).score() : Double.NaN;
            misses[i] = all.get(i).feasible() ? Double.NaN : all.get(i).score();
        }
        XYChart c = PngCharts.panel(WIDTH, PANEL + 20, title, CliMsg.PLOT_SIMULATION.text(), result.objective().label());
        PngCharts.points(c, CliMsg.PLOT_EACH_SIMULATION.text(), n, feasible, PlotStyle.OTHER_RUN, false);
        PngCharts.points(c, CliMsg.PLOT_MISSES.text(), n, misses, PlotStyle.MISSES, false);
        double[] best = result.bestSoFar();
        if (java.util.Arrays.stream(best).anyMatch(Double::isFinite)) {
            PngCharts.line(c, CliMsg.PLOT_BEST_SO_FAR.text(), n, best, Math.min(n.length, best.length), PlotStyle.BEST_SO_FAR);
        }
        return c;
    }
}
