package org.parpe.cli.diagram;

import org.parpe.cli.text.CliMsg;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Arc2D;
import java.awt.geom.Area;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import org.parpe.cli.plot.Canvas;
import org.parpe.core.diagram.Scene;

/** Draws a {@link Scene} with Java2D on the command line's white {@link Canvas}, for PNG files. */
public final class ScenePng {
    /** The smallest width asked for with --width, pixels. */
    public static final int MIN_SIDE = 16;
    /** The largest width asked for with --width, pixels: 10 000 × 10 000 takes 400 MB to draw. */
    public static final int MAX_WIDTH = 10_000;
    /** The widest and tallest PNG drawn, px: what image viewers and browsers open. */
    static final int MAX_SIDE = 32_767;
    /** The most pixels of a PNG drawn: 64 Mi, a 256 MiB image in memory. */
    static final long MAX_PIXELS = 64L << 20;

    private ScenePng() {
    }

    /**
     * Why {@code scene} is not drawn as a PNG, or {@code null} when it can be: a picture beyond
     * {@link #MAX_SIDE} or {@link #MAX_PIXELS} (10 000 {@code <main>} entries made a program
     * lane over a million pixels wide, gigabytes in memory). SVG has no such limit.
     */
    public static String tooLarge(Scene scene, int width) {
        long height = height(scene, width);
        long pixels = (long) width * height;
        if (width <= MAX_SIDE && height <= MAX_SIDE && pixels <= MAX_PIXELS) {
            return null;
        }
        return CliMsg.PNG_TOO_LARGE.text(width, height, MAX_SIDE, MAX_PIXELS, MAX_PIXELS * 4 >> 20);
    }

    /** The height of the scene drawn {@code width} pixels wide (at least 1). */
    static long height(Scene scene, int width) {
        return Math.max(1, Math.round((double) scene.height() * width / scene.width()));
    }

    /** The scene scaled to {@code width} pixels wide, its height in proportion ({@link #height}). */
    public static BufferedImage draw(Scene scene, int width) {
        Canvas c = Canvas.white(width, (int) height(scene, width));
        Graphics2D g = c.graphics();
        if (width != scene.width()) {
            g.scale((double) width / scene.width(), (double) width / scene.width());
            // glyph advances of the scaled size, not rounded to whole pixels of the scene's size
            g.setRenderingHint(RenderingHints.KEY_FRACTIONALMETRICS, RenderingHints.VALUE_FRACTIONALMETRICS_ON);
        }
        try {
            for (Scene.Shape s : scene.shapes()) {
                if (s instanceof Scene.Rect r) {
                    Rectangle2D box = new Rectangle2D.Double(r.x(), r.y(), r.w(), r.h());
                    fillAndStroke(g, box, r.fill(), r.stroke(), r.strokeWidth());
                } else if (s instanceof Scene.Line l) {
                    g.setColor(new Color(l.stroke()));
                    g.setStroke(l.dash() > 0 ? new BasicStroke((float) l.width(), BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER,
                            10, new float[] {(float) l.dash()}, 0) : new BasicStroke((float) l.width()));
                    g.draw(new Line2D.Double(l.x1(), l.y1(), l.x2(), l.y2()));
                } else if (s instanceof Scene.Sector a) {
                    fillAndStroke(g, sector(a), a.fill(), a.stroke(), 1);
                } else {
                    Scene.Text t = (Scene.Text) s;
                    g.setFont(new Font(Font.SANS_SERIF, t.bold() ? Font.BOLD : Font.PLAIN, (int) Math.round(t.size())));
                    g.setColor(new Color(t.color()));
                    double w = g.getFontMetrics().stringWidth(t.text());
                    double x = t.anchor() < 0 ? t.x() : t.anchor() == 0 ? t.x() - w / 2 : t.x() - w;
                    g.drawString(t.text(), (float) x, (float) t.y());
                }
            }
        } finally {
            g.dispose();
        }
        return c.image();
    }

    private static void fillAndStroke(Graphics2D g, java.awt.Shape shape, int fill, int stroke, double width) {
        if (fill != Scene.NONE) {
            g.setColor(new Color(fill));
            g.fill(shape);
        }
        if (stroke != Scene.NONE) {
            g.setColor(new Color(stroke));
            g.setStroke(new BasicStroke((float) width));
            g.draw(shape);
        }
    }

    /** Java2D measures angles counter-clockwise from 3 o'clock; the scene clockwise from the top. */
    private static java.awt.Shape sector(Scene.Sector a) {
        double start = 90 - a.to() * 360;
        double extent = (a.to() - a.from()) * 360;
        Area outer = new Area(new Arc2D.Double(a.cx() - a.r1(), a.cy() - a.r1(), 2 * a.r1(), 2 * a.r1(), start, extent,
                Arc2D.PIE));
        if (a.r0() > 0) {
            outer.subtract(new Area(new Ellipse2D.Double(a.cx() - a.r0(), a.cy() - a.r0(), 2 * a.r0(), 2 * a.r0())));
        }
        return outer;
    }
}
