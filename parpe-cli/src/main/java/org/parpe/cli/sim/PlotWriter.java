package org.parpe.cli.sim;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.Stroke;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.parpe.cli.Canvas;

/**
 * Draws {@code --plot}: one panel per moving module (at most {@value #MAX_PANELS}), commanded
 * angle dashed and measured angle solid, with time and angle axes, ticks, units and a legend.
 * Headless: plain {@link BufferedImage} drawing, no window system.
 */
final class PlotWriter {
    private static final int MAX_PANELS = 8;
    private static final int WIDTH = 1200;
    private static final int PANEL = 140;
    private static final int TOP = 70;
    private static final int LEFT = 130;
    private static final int RIGHT = 30;
    private static final int BOTTOM = 60;
    private static final int GAP = 14;
    private static final Color[] COLORS = {new Color(0x1f77b4), new Color(0xd62728), new Color(0x2ca02c),
        new Color(0x9467bd), new Color(0xff7f0e), new Color(0x17becf), new Color(0x8c564b), new Color(0xe377c2)};

    private final PlotRecorder data;

    PlotWriter(PlotRecorder data) {
        this.data = data;
    }

    void write(OutputStream out) throws IOException {
        List<Integer> shown = chooseModules();
        int height = TOP + shown.size() * (PANEL + GAP) + BOTTOM;
        Canvas canvas = Canvas.white(WIDTH, height);
        BufferedImage img = canvas.image();
        Graphics2D g = canvas.graphics();
        header(g, shown.size());
        double tEnd = data.samples() == 0 ? 1 : Math.max(data.time(data.samples() - 1), data.dt());
        for (int p = 0; p < shown.size(); p++) {
            int top = TOP + p * (PANEL + GAP);
            panel(g, shown.get(p), top, tEnd, p == shown.size() - 1, COLORS[p % COLORS.length]);
        }
        g.dispose();
        if (!ImageIO.write(img, "png", out)) {
            throw new IOException("no PNG writer available");
        }
    }

    /** The modules whose commanded or measured angle changes, in ID order, at most {@value #MAX_PANELS}. */
    private List<Integer> chooseModules() {
        List<Integer> moving = new ArrayList<>();
        for (int m = 0; m < data.moduleCount() && moving.size() < MAX_PANELS; m++) {
            double lo = Double.POSITIVE_INFINITY;
            double hi = Double.NEGATIVE_INFINITY;
            for (int s = 0; s < data.samples(); s++) {
                lo = Math.min(lo, data.commanded(s, m));
                hi = Math.max(hi, data.commanded(s, m));
            }
            if (hi - lo > 0.5) {
                moving.add(m);
            }
        }
        for (int m = 0; moving.isEmpty() && m < Math.min(MAX_PANELS, data.moduleCount()); m++) {
            moving.add(m);
        }
        return moving;
    }

    private void header(Graphics2D g, int panels) {
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 18));
        String more = panels < data.moduleCount() ? String.format(Locale.ROOT, " (%d of %d modules, those that move)",
                panels, data.moduleCount()) : "";
        g.drawString("Joint angles over time" + more, LEFT, 28);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
        int x = LEFT;
        g.setStroke(dashed());
        g.setColor(Color.DARK_GRAY);
        g.drawLine(x, 50, x + 40, 50);
        g.setColor(Color.BLACK);
        g.drawString("commanded", x + 48, 55);
        x += 160;
        g.setStroke(new BasicStroke(2f));
        g.setColor(COLORS[0]);
        g.drawLine(x, 50, x + 40, 50);
        g.setColor(Color.BLACK);
        g.drawString("measured (simulator)", x + 48, 55);
    }

    private void panel(Graphics2D g, int m, int top, double tEnd, boolean last, Color color) {
        int w = WIDTH - LEFT - RIGHT;
        double range = yRange(m);
        g.setStroke(new BasicStroke(1f));
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        double yStep = range <= 30 ? 15 : range <= 60 ? 30 : 45;
        for (double v = -Math.floor(range / yStep) * yStep; v <= range + 1e-9; v += yStep) {
            int y = yPix(v, range, top);
            g.setColor(new Color(0xe6e6e6));
            g.drawLine(LEFT, y, LEFT + w, y);
            g.setColor(Color.BLACK);
            String label = String.format(Locale.ROOT, "%.0f°", v);
            g.drawString(label, LEFT - 8 - g.getFontMetrics().stringWidth(label), y + 4);
        }
        double xStep = niceStep(tEnd, 10);
        for (double t = 0; t <= tEnd + 1e-9; t += xStep) {
            int x = LEFT + (int) Math.round(t / tEnd * w);
            g.setColor(new Color(0xe6e6e6));
            g.drawLine(x, top, x, top + PANEL);
            g.setColor(Color.BLACK);
            g.drawLine(x, top + PANEL, x, top + PANEL + 4);
            if (last) {
                String label = String.format(Locale.ROOT, xStep < 1 ? "%.1f" : "%.0f", t);
                g.drawString(label, x - g.getFontMetrics().stringWidth(label) / 2, top + PANEL + 18);
            }
        }
        g.setColor(Color.BLACK);
        g.drawRect(LEFT, top, w, PANEL);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
        g.drawString("module " + data.id(m), 8, top + 16);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.drawString("angle (°)", 8, top + 34);
        if (last) {
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
            g.drawString("time (s)", LEFT + w / 2 - 25, top + PANEL + 40);
        }
        g.setClip(LEFT, top, w, PANEL);
        g.setColor(Color.DARK_GRAY);
        g.setStroke(dashed());
        g.draw(curve(m, true, range, top, tEnd, w));
        g.setColor(color);
        g.setStroke(new BasicStroke(2f));
        g.draw(curve(m, false, range, top, tEnd, w));
        g.setClip(null);
    }

    private Path2D curve(int m, boolean commanded, double range, int top, double tEnd, int w) {
        Path2D.Double path = new Path2D.Double();
        boolean started = false;
        for (int s = 0; s < data.samples(); s++) {
            double v = commanded ? data.commanded(s, m) : data.measured(s, m);
            if (!Double.isFinite(v)) {
                started = false;
                continue;
            }
            double x = LEFT + data.time(s) / tEnd * w;
            double y = top + PANEL / 2.0 - v / range * (PANEL / 2.0);
            if (started) {
                path.lineTo(x, y);
            } else {
                path.moveTo(x, y);
                started = true;
            }
        }
        return path;
    }

    /** Symmetric angle range covering the data, a multiple of 15°, at least 15°, at most 90°. */
    private double yRange(int m) {
        double max = 0;
        for (int s = 0; s < data.samples(); s++) {
            max = Math.max(max, Math.abs(data.commanded(s, m)));
            double v = data.measured(s, m);
            max = Double.isFinite(v) ? Math.max(max, Math.abs(v)) : max;
        }
        return Math.min(90, Math.max(15, Math.ceil(max / 15) * 15));
    }

    private static int yPix(double v, double range, int top) {
        return (int) Math.round(top + PANEL / 2.0 - v / range * (PANEL / 2.0));
    }

    /** A 1, 2 or 5 × 10^k step giving about {@code ticks} intervals over {@code span}. */
    static double niceStep(double span, int ticks) {
        double raw = span / ticks;
        double p = Math.pow(10, Math.floor(Math.log10(raw)));
        double f = raw / p;
        return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * p;
    }

    private static Stroke dashed() {
        return new BasicStroke(1.6f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f);
    }
}
