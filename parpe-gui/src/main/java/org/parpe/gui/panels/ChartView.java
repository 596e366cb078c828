package org.parpe.gui.panels;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.WeakHashMap;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Event;
import org.parpe.core.plot.NiceTicks;
import org.parpe.core.plot.PlotStyle;

/**
 * The IDE's one chart component (the live joint-angle plot and the sweep's results plot): axes
 * with the core's {@link NiceTicks}, the one {@link PlotStyle} (commanded dashed, measured solid),
 * the theme's paper and ink (a dark GTK theme gives a dark chart), and the IDE's zoom
 * (Ctrl + / Ctrl − / Ctrl 0: larger text and thicker lines for a projector). What it shows is
 * given as a {@link Content} that draws series in a {@link Frame}.
 */
public final class ChartView {
    private static final java.util.Set<ChartView> LIVE = Collections.newSetFromMap(new WeakHashMap<>());
    private static int zoom;

    private final Canvas canvas;
    private String title = "";
    private String xLabel = "";
    private String message;
    private double[] xRange;
    private double[] yRange;
    private Content content;
    private final List<Drawn> drawn = new ArrayList<>();
    private final List<Drawn> legend = new ArrayList<>();

    /** What a chart shows: series drawn in the frame (on the UI thread, at each paint). */
    @FunctionalInterface
    public interface Content {
        void draw(Frame f);
    }

    /** A series as drawn: its name, colour (0xRRGGBB), whether dashed or hollow, its line width in pixels. */
    public record Drawn(String name, int rgb, boolean dashed, boolean points, boolean hollow, int width) {
    }

    public ChartView(Composite parent, int style) {
        canvas = new Canvas(parent, style | SWT.DOUBLE_BUFFERED | SWT.NO_BACKGROUND);
        canvas.addListener(SWT.Paint, this::paint);
        LIVE.add(this);
        canvas.addListener(SWT.Dispose, e -> LIVE.remove(this));
        applyZoom();
    }

    public Canvas control() {
        return canvas;
    }

    /** Shows {@code c} within the ranges (each {lo, hi}; widened when empty), with the title and x axis title. */
    public void show(String chartTitle, String xTitle, double[] xs, double[] ys, Content c) {
        title = chartTitle;
        xLabel = xTitle;
        xRange = widen(xs);
        yRange = widen(ys);
        content = c;
        message = null;
        redraw();
    }

    /** Shows a sentence instead of a chart (nothing to plot yet). */
    public void message(String text) {
        message = text;
        content = null;
        redraw();
    }

    public void redraw() {
        if (!canvas.isDisposed()) {
            canvas.redraw();
        }
    }

    /** Larger or smaller text and lines in every chart: {@code steps} of 2 points (0: normal). */
    public static void zoomAll(int steps) {
        zoom = steps;
        for (ChartView v : new ArrayList<>(LIVE)) {
            v.applyZoom();
            v.redraw();
        }
    }

    private void applyZoom() {
        if (!canvas.isDisposed()) {
            Zoom.apply(canvas, canvas.getDisplay().getSystemFont(), zoom);
        }
    }

    /** How much the lines are thickened: the font's size to its normal size. */
    private float scale() {
        int normal = canvas.getDisplay().getSystemFont().getFontData()[0].getHeight();
        int now = canvas.getFont().getFontData()[0].getHeight();
        return Math.max(0.5f, now / (float) Math.max(1, normal));
    }

    /** The series of the last paint, in drawing order (what a test or a screen reader may ask). */
    public List<Drawn> drawn() {
        return List.copyOf(drawn);
    }

    private static double[] widen(double[] r) {
        double lo = r[0];
        double hi = r[1];
        if (!Double.isFinite(lo) || !Double.isFinite(hi)) {
            return new double[] {0, 1};
        }
        if (hi > lo) {
            return new double[] {lo, hi};
        }
        double pad = lo == 0 ? 1 : Math.abs(lo) * 0.1;
        return new double[] {lo - pad, hi + pad};
    }

    private void paint(Event e) {
        GC gc = e.gc;
        Rectangle area = canvas.getClientArea();
        gc.setFont(canvas.getFont());
        gc.setBackground(Theme.paper());
        gc.fillRectangle(area);
        gc.setForeground(Theme.ink());
        drawn.clear();
        legend.clear();
        int lineH = gc.getFontMetrics().getHeight();
        if (message != null || content == null) {
            // wrapped at the chart's width: a longer language or the zoomed font would run past its edge
            org.eclipse.swt.graphics.TextLayout text = new org.eclipse.swt.graphics.TextLayout(gc.getDevice());
            try {
                text.setFont(canvas.getFont());
                text.setText(message == null ? "" : message);
                text.setWidth(Math.max(1, area.width - lineH));
                text.draw(gc, lineH / 2, lineH / 2);
            } finally {
                text.dispose();
            }
            return;
        }
        int left = gc.textExtent("-0.0000").x + lineH / 2;
        Frame f = new Frame(gc, left, area.width - lineH, lineH * 3 / 2, area.height - lineH * 4, scale());
        if (f.right - f.left < 20 || f.bottom - f.top < 20) {
            return;
        }
        f.axes();
        gc.setAntialias(SWT.ON);
        gc.setClipping(f.left, f.top, f.right - f.left + 1, f.bottom - f.top + 1);
        content.draw(f);
        gc.setClipping((Rectangle) null);
        gc.setLineStyle(SWT.LINE_SOLID);
        gc.setLineWidth(1);
        f.legendRow(area.height - lineH - 2);
    }

    /** The plot area of one paint: data to pixels, and the series drawn in it. */
    public final class Frame {
        private final GC gc;
        private final int left;
        private final int right;
        private final int top;
        private final int bottom;
        private final float scale;

        private Frame(GC gc, int left, int right, int top, int bottom, float scale) {
            this.gc = gc;
            this.left = left;
            this.right = right;
            this.top = top;
            this.bottom = bottom;
            this.scale = scale;
        }

        public int px(double x) {
            return left + (int) Math.round((x - xRange[0]) / (xRange[1] - xRange[0]) * (right - left));
        }

        public int py(double y) {
            double c = Math.max(yRange[0] - (yRange[1] - yRange[0]), Math.min(yRange[1] + (yRange[1] - yRange[0]), y));
            return bottom - (int) Math.round((c - yRange[0]) / (yRange[1] - yRange[0]) * (bottom - top));
        }

        /**
         * A curve through the first {@code n} finite points: dashed for a commanded angle,
         * solid otherwise ({@link PlotStyle#dashed}); a gap where a value is missing.
         */
        public void line(String name, double[] x, double[] y, int n, int rgb, boolean commanded) {
            int width = Math.max(1, Math.round(PlotStyle.LINE_WIDTH * scale));
            boolean dashed = PlotStyle.dashed(commanded);
            Color c = color(rgb);
            gc.setForeground(c);
            gc.setLineWidth(width);
            if (dashed) {
                float[] d = PlotStyle.dash(scale);
                gc.setLineDash(new int[] {Math.max(1, Math.round(d[0])), Math.max(1, Math.round(d[1]))});
            } else {
                gc.setLineStyle(SWT.LINE_SOLID);
            }
            int lastX = Integer.MIN_VALUE;
            int lastY = 0;
            for (int i = 0; i < n; i++) {
                if (!Double.isFinite(x[i]) || !Double.isFinite(y[i])) {
                    lastX = Integer.MIN_VALUE;
                    continue;
                }
                int xp = px(x[i]);
                int yp = py(y[i]);
                if (lastX != Integer.MIN_VALUE) {
                    gc.drawLine(lastX, lastY, xp, yp);
                }
                lastX = xp;
                lastY = yp;
            }
            gc.setLineStyle(SWT.LINE_SOLID);
            c.dispose();
            keep(new Drawn(name, rgb, dashed, false, false, width));
        }

        /** Dots (filled) or rings (hollow: set apart, as a run that fell over) at the finite points. */
        public void points(String name, double[] x, double[] y, int n, int rgb, boolean hollow) {
            int r = Math.max(3, Math.round(3.5f * scale));
            Color c = color(rgb);
            gc.setForeground(c);
            gc.setBackground(c);
            gc.setLineWidth(Math.max(1, Math.round(1.5f * scale)));
            boolean any = false;
            for (int i = 0; i < n; i++) {
                if (Double.isFinite(x[i]) && Double.isFinite(y[i])) {
                    any = true;
                    if (hollow) {
                        gc.drawOval(px(x[i]) - r, py(y[i]) - r, 2 * r, 2 * r);
                    } else {
                        gc.fillOval(px(x[i]) - r, py(y[i]) - r, 2 * r + 1, 2 * r + 1);
                    }
                }
            }
            c.dispose();
            if (any) {
                keep(new Drawn(name, rgb, false, true, hollow, 1));
            }
        }

        private void keep(Drawn d) {
            drawn.add(d);
            if (d.name() != null && legend.stream().noneMatch(l -> l.name().equals(d.name()))) {
                legend.add(d);
            }
        }

        private Color color(int rgb) {
            return new Color((rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF);
        }

        private void axes() {
            int lineH = gc.getFontMetrics().getHeight();
            gc.setForeground(Theme.faint());
            // At least three intervals: a short plot still shows a scale, not a lone 0.
            int yTicks = Math.max(3, (bottom - top) / (2 * lineH));
            double yStep = NiceTicks.step(yRange[1] - yRange[0], yTicks);
            for (double v : NiceTicks.within(yRange[0], yRange[1], yTicks)) {
                gc.drawLine(left, py(v), right, py(v));
                String s = NiceTicks.label(v, yStep);
                gc.setForeground(Theme.ink());
                gc.drawText(s, left - 4 - gc.textExtent(s).x, py(v) - lineH / 2, true);
                gc.setForeground(Theme.faint());
            }
            int xTicks = Math.max(2, (right - left) / (gc.textExtent("00000.0").x * 2));
            double step = NiceTicks.step(xRange[1] - xRange[0], xTicks);
            for (double v : NiceTicks.within(xRange[0], xRange[1], xTicks)) {
                gc.drawLine(px(v), bottom, px(v), bottom + 4);
                String s = NiceTicks.label(v, step);
                gc.setForeground(Theme.ink());
                gc.drawText(s, px(v) - gc.textExtent(s).x / 2, bottom + 4, true);
                gc.setForeground(Theme.faint());
            }
            gc.drawRectangle(left, top, right - left, bottom - top);
            gc.setForeground(Theme.ink());
            gc.drawText(title, left, 2, true);
            Point xl = gc.textExtent(xLabel);
            gc.drawText(xLabel, right - xl.x, bottom + 4 + lineH, true);
        }

        /** The key of the series drawn: a sample of each line or dot, then its name. */
        private void legendRow(int y) {
            int lineH = gc.getFontMetrics().getHeight();
            int x = 4;
            for (Drawn d : legend) {
                Color c = color(d.rgb());
                gc.setForeground(c);
                gc.setBackground(c);
                int mid = y + lineH / 2;
                if (d.points()) {
                    int r = lineH / 4;
                    if (d.hollow()) {
                        gc.drawOval(x + lineH / 2 - r, mid - r, 2 * r, 2 * r);
                    } else {
                        gc.fillOval(x + lineH / 2 - r, mid - r, 2 * r, 2 * r);
                    }
                } else {
                    gc.setLineWidth(d.width());
                    if (d.dashed()) {
                        float[] dd = PlotStyle.dash(scale);
                        gc.setLineDash(new int[] {Math.max(1, Math.round(dd[0])), Math.max(1, Math.round(dd[1]))});
                    }
                    gc.drawLine(x, mid, x + lineH * 2, mid);
                    gc.setLineStyle(SWT.LINE_SOLID);
                    gc.setLineWidth(1);
                }
                c.dispose();
                gc.setForeground(Theme.ink());
                gc.drawText(d.name(), x + lineH * 2 + 4, y, true);
                x += lineH * 2 + 4 + gc.textExtent(d.name()).x + lineH;
            }
        }
    }
}
