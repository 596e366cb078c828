package org.parpe.cli.sweep;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Predicate;
import org.parpe.cli.Canvas;
import org.parpe.sim.sweep.Axis;
import org.parpe.sim.sweep.Evaluation;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.OptimizationResult;
import org.parpe.sim.sweep.SweepResult;
import org.parpe.sim.sweep.SweepRow;

/**
 * The PNG plots of the sweep commands: the objective over each varied parameter (every run a
 * grey dot, a run whose robot fell over a hollow red ring, the best run at each value joined by a
 * line, under the same rule as the summary's best), and an optimisation's convergence
 * (every evaluation a dot, the best so far a line).
 */
final class Plots {
    private static final int WIDTH = 1000;
    private static final int PANEL = 260;
    private static final int LEFT = 110;
    private static final int TOP = 60;
    private static final int GAP = 70;
    private static final Color MISSES = new Color(0xfdae61);

    private Plots() {
    }

    /** One panel per axis: {@code objective} of every run over the axis's values. */
    static void sweep(OutputStream out, String title, List<Axis> axes, List<SweepRow> rows, Objective objective,
                      boolean countFallen) throws IOException {
        Predicate<SweepRow> rule = SweepResult.rule(countFallen);
        int height = TOP + axes.size() * (PANEL + GAP);
        Canvas canvas = Canvas.white(WIDTH, height);
        BufferedImage img = canvas.image();
        Graphics2D g = canvas.graphics();
        title(g, title);
        double[] scores = rows.stream().mapToDouble(r -> r.ok() ? objective.of(r) : Double.NaN).toArray();
        for (int a = 0; a < axes.size(); a++) {
            String name = axes.get(a).name();
            double[] xs = rows.stream().mapToDouble(r -> r.values().get(name)).toArray();
            Chart c = new Chart(g, LEFT, TOP + a * (PANEL + GAP), WIDTH - LEFT - 40, PANEL, Chart.range(xs),
                    Chart.range(scores));
            c.axes(name, objective.label());
            Map<Double, Double> best = new TreeMap<>();
            for (int i = 0; i < xs.length; i++) {
                if (rows.get(i).fell()) {
                    c.ring(xs[i], scores[i], Chart.RED, 8);
                } else {
                    c.dot(xs[i], scores[i], Chart.GREY, 6);
                }
                if (SweepResult.contender(rows.get(i), objective, rule)) {
                    best.merge(xs[i], scores[i], Math::max);
                }
            }
            double[] bx = best.keySet().stream().mapToDouble(Double::doubleValue).toArray();
            double[] by = best.values().stream().mapToDouble(Double::doubleValue).toArray();
            c.line(bx, by, Chart.BLUE, 2f);
            for (int i = 0; i < bx.length; i++) {
                c.dot(bx[i], by[i], Chart.BLUE, 7);
            }
        }
        fallenLegend(g, legend(g, "each run", "best run at this value", Chart.BLUE), countFallen);
        g.dispose();
        Chart.write(img, out);
    }

    /** Every evaluation's score and the best feasible score so far, over the evaluations. */
    static void convergence(OutputStream out, String title, OptimizationResult result) throws IOException {
        Canvas canvas = Canvas.white(WIDTH, TOP + PANEL + GAP + 20);
        BufferedImage img = canvas.image();
        Graphics2D g = canvas.graphics();
        title(g, title);
        List<Evaluation> all = result.evaluations();
        double[] n = new double[all.size()];
        double[] scores = new double[all.size()];
        for (int i = 0; i < n.length; i++) {
            n[i] = i + 1;
            scores[i] = all.get(i).score();
        }
        double[] best = result.bestSoFar();
        Chart c = new Chart(g, LEFT, TOP, WIDTH - LEFT - 40, PANEL + 20, new double[] {1, Math.max(1, n.length)},
                Chart.range(scores));
        c.axes("simulation", result.objective().label());
        for (int i = 0; i < n.length; i++) {
            c.dot(n[i], scores[i], all.get(i).feasible() ? Chart.GREY : MISSES, 5);
        }
        c.line(n, best, Chart.RED, 2.5f);
        legend(g, "each simulation (orange: misses a constraint)", "best so far", Chart.RED);
        g.dispose();
        Chart.write(img, out);
    }

    private static void title(Graphics2D g, String title) {
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
        g.drawString(title, LEFT, 28);
    }

    /** The key of the fallen runs' rings, from {@code x} on the legend's line. */
    private static void fallenLegend(Graphics2D g, int x, boolean counted) {
        g.setColor(Chart.RED);
        g.setStroke(new java.awt.BasicStroke(1.5f));
        g.drawOval(x + 24, 40, 7, 7);
        g.setColor(Color.DARK_GRAY);
        g.drawString(counted ? "fell over" : "fell over (never best)", x + 36, 48);
    }

    /** Draws the legend of the dots and the line; returns the x where it ends. */
    private static int legend(Graphics2D g, String dots, String line, Color lineColor) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        int x = LEFT + 420;
        g.setColor(Chart.GREY);
        g.fillOval(x, 40, 7, 7);
        g.setColor(Color.DARK_GRAY);
        g.drawString(dots, x + 12, 48);
        x += 12 + g.getFontMetrics().stringWidth(dots) + 24;
        g.setColor(lineColor);
        g.fillRect(x, 43, 20, 3);
        g.setColor(Color.DARK_GRAY);
        g.drawString(line, x + 26, 48);
        return x + 26 + g.getFontMetrics().stringWidth(line);
    }
}
