package org.parpe.cli.sweep;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.util.Locale;
import javax.imageio.ImageIO;

/**
 * One panel of a PNG chart: a frame, x and y axes with round tick values and labels, and the
 * mapping of data to pixels. Headless: plain {@link BufferedImage} drawing.
 */
final class Chart {
    static final Color BLUE = new Color(0x1f77b4);
    static final Color RED = new Color(0xd62728);
    static final Color GREY = new Color(0xb0b0b0);

    private final Graphics2D g;
    private final int left;
    private final int top;
    private final int width;
    private final int height;
    private final double x0;
    private final double x1;
    private final double y0;
    private final double y1;

    /** A panel at ({@code left}, {@code top}) of {@code width}×{@code height} pixels for the given ranges. */
    Chart(Graphics2D g, int left, int top, int width, int height, double[] xRange, double[] yRange) {
        this.g = g;
        this.left = left;
        this.top = top;
        this.width = width;
        this.height = height;
        double[] x = widen(xRange);
        double[] y = widen(yRange);
        this.x0 = x[0];
        this.x1 = x[1];
        this.y0 = y[0];
        this.y1 = y[1];
    }

    /** Writes {@code img} as PNG. */
    static void write(BufferedImage img, OutputStream out) throws IOException {
        if (!ImageIO.write(img, "png", out)) {
            throw new IOException("no PNG writer available");
        }
    }

    /** A range with some room around the data; a single value gets a unit-wide range. */
    private static double[] widen(double[] r) {
        double lo = r[0];
        double hi = r[1];
        if (!Double.isFinite(lo) || !Double.isFinite(hi)) {
            return new double[] {0, 1};
        }
        if (hi - lo < 1e-12) {
            double pad = Math.max(Math.abs(lo) * 0.1, 0.5);
            return new double[] {lo - pad, hi + pad};
        }
        double pad = (hi - lo) * 0.05;
        return new double[] {lo - pad, hi + pad};
    }

    /** The minimum and maximum of the finite values, or NaNs when there are none. */
    static double[] range(double[] values) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (double v : values) {
            if (Double.isFinite(v)) {
                lo = Math.min(lo, v);
                hi = Math.max(hi, v);
            }
        }
        return lo <= hi ? new double[] {lo, hi} : new double[] {Double.NaN, Double.NaN};
    }

    int px(double x) {
        return left + (int) Math.round((x - x0) / (x1 - x0) * width);
    }

    int py(double y) {
        return top + height - (int) Math.round((y - y0) / (y1 - y0) * height);
    }

    /** The frame, grid lines, tick labels and axis titles. */
    void axes(String xLabel, String yLabel) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        double xs = niceStep(x1 - x0, 6);
        for (double v = Math.ceil(x0 / xs) * xs; v <= x1 + 1e-9 * xs; v += xs) {
            g.setColor(new Color(0xeeeeee));
            g.drawLine(px(v), top, px(v), top + height);
            g.setColor(Color.DARK_GRAY);
            String s = label(v, xs);
            g.drawString(s, px(v) - g.getFontMetrics().stringWidth(s) / 2, top + height + 16);
        }
        double ys = niceStep(y1 - y0, 5);
        for (double v = Math.ceil(y0 / ys) * ys; v <= y1 + 1e-9 * ys; v += ys) {
            g.setColor(new Color(0xeeeeee));
            g.drawLine(left, py(v), left + width, py(v));
            g.setColor(Color.DARK_GRAY);
            String s = label(v, ys);
            g.drawString(s, left - 8 - g.getFontMetrics().stringWidth(s), py(v) + 4);
        }
        g.setColor(Color.BLACK);
        g.drawRect(left, top, width, height);
        g.drawString(xLabel, left + width / 2 - g.getFontMetrics().stringWidth(xLabel) / 2, top + height + 34);
        Graphics2D r = (Graphics2D) g.create();
        r.rotate(-Math.PI / 2);
        r.drawString(yLabel, -(top + height / 2) - r.getFontMetrics().stringWidth(yLabel) / 2, left - 62);
        r.dispose();
    }

    /** A dot at ({@code x}, {@code y}). */
    void dot(double x, double y, Color c, int size) {
        if (Double.isFinite(x) && Double.isFinite(y)) {
            g.setColor(c);
            g.fillOval(px(x) - size / 2, py(y) - size / 2, size, size);
        }
    }

    /** A hollow ring at ({@code x}, {@code y}): a point set apart from the dots. */
    void ring(double x, double y, Color c, int size) {
        if (Double.isFinite(x) && Double.isFinite(y)) {
            g.setColor(c);
            g.setStroke(new BasicStroke(1.5f));
            g.drawOval(px(x) - size / 2, py(y) - size / 2, size, size);
        }
    }

    /** A polyline through the finite points. */
    void line(double[] xs, double[] ys, Color c, float width) {
        g.setColor(c);
        g.setStroke(new BasicStroke(width));
        int lastX = Integer.MIN_VALUE;
        int lastY = 0;
        for (int i = 0; i < xs.length; i++) {
            if (!Double.isFinite(xs[i]) || !Double.isFinite(ys[i])) {
                lastX = Integer.MIN_VALUE;
                continue;
            }
            int x = px(xs[i]);
            int y = py(ys[i]);
            if (lastX != Integer.MIN_VALUE) {
                g.drawLine(lastX, lastY, x, y);
            }
            lastX = x;
            lastY = y;
        }
        g.setStroke(new BasicStroke(1));
    }

    /** A step of 1, 2 or 5 × 10^k giving about {@code ticks} ticks over {@code span}. */
    static double niceStep(double span, int ticks) {
        double raw = span / ticks;
        double mag = Math.pow(10, Math.floor(Math.log10(raw)));
        double n = raw / mag;
        return (n < 1.5 ? 1 : n < 3.5 ? 2 : n < 7.5 ? 5 : 10) * mag;
    }

    private static String label(double v, double step) {
        int decimals = Math.max(0, (int) -Math.floor(Math.log10(step) + 1e-9));
        return String.format(Locale.ROOT, "%." + decimals + "f", Math.abs(v) < step * 1e-6 ? 0.0 : v);
    }
}
