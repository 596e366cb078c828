package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.List;

/**
 * A drawing made of a few primitives (rectangles, lines, annular sectors, text) in pixels,
 * laid out once by {@link Layouts} and drawn by any back end: {@link #svg()} writes SVG text
 * here; the command line draws PNGs with Java2D and the IDE can draw with SWT from the same
 * list. Colours are {@code 0xRRGGBB}; {@link #NONE} means not filled or not stroked.
 */
public final class Scene {
    /** No colour: not filled, or not stroked. */
    public static final int NONE = -1;

    /** A drawing primitive. */
    public sealed interface Shape permits Rect, Line, Sector, Text {
    }

    /** A rectangle; {@code source} is the place it stands for, or {@code null}. */
    public record Rect(double x, double y, double w, double h, int fill, int stroke, double strokeWidth,
                       org.parpe.core.diag.SourcePos source) implements Shape {
    }

    /** A straight line; {@code dash} 0 for solid. */
    public record Line(double x1, double y1, double x2, double y2, int stroke, double width, double dash)
            implements Shape {
    }

    /**
     * The part of a ring between radii {@code r0 < r1} and fractions {@code from < to} of a turn,
     * 0 at the top, clockwise ({@code r0 = 0} is a pie slice).
     */
    public record Sector(double cx, double cy, double r0, double r1, double from, double to, int fill, int stroke,
                         org.parpe.core.diag.SourcePos source) implements Shape {
    }

    /** Text whose baseline starts at, is centred on or ends at {@code x} ({@code anchor} −1, 0, 1). */
    public record Text(double x, double y, String text, double size, int anchor, int color, boolean bold)
            implements Shape {
    }

    private final int width;
    private final int height;
    private final List<Shape> shapes = new ArrayList<>();

    /** An empty {@code width} × {@code height} drawing. */
    public Scene(int width, int height) {
        this.width = width;
        this.height = height;
    }

    /** The width in pixels. */
    public int width() {
        return width;
    }

    /** The height in pixels. */
    public int height() {
        return height;
    }

    /** The shapes, in drawing order. */
    public List<Shape> shapes() {
        return java.util.Collections.unmodifiableList(shapes);
    }

    /** Adds a shape on top of the others. */
    public Scene add(Shape s) {
        shapes.add(s);
        return this;
    }

    /** The point at fraction {@code f} of a turn (0 at the top, clockwise) on a circle. */
    public static double[] onCircle(double cx, double cy, double r, double f) {
        double a = 2 * Math.PI * f;
        return new double[] {cx + r * Math.sin(a), cy - r * Math.cos(a)};
    }

    /** The drawing as a standalone SVG document. */
    public String svg() {
        StringBuilder s = new StringBuilder(64 + shapes.size() * 96);
        s.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(width).append("\" height=\"").append(height)
                .append("\" viewBox=\"0 0 ").append(width).append(' ').append(height)
                .append("\" font-family=\"DejaVu Sans, sans-serif\">\n");
        s.append("<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n");
        for (Shape shape : shapes) {
            if (shape instanceof Rect r) {
                s.append("<rect x=\"").append(n(r.x())).append("\" y=\"").append(n(r.y())).append("\" width=\"")
                        .append(n(r.w())).append("\" height=\"").append(n(r.h())).append('"');
                paint(s, r.fill(), r.stroke(), r.strokeWidth());
                s.append("/>\n");
            } else if (shape instanceof Line l) {
                s.append("<line x1=\"").append(n(l.x1())).append("\" y1=\"").append(n(l.y1())).append("\" x2=\"")
                        .append(n(l.x2())).append("\" y2=\"").append(n(l.y2())).append('"');
                paint(s, NONE, l.stroke(), l.width());
                if (l.dash() > 0) {
                    s.append(" stroke-dasharray=\"").append(n(l.dash())).append('"');
                }
                s.append("/>\n");
            } else if (shape instanceof Sector c) {
                s.append("<path d=\"").append(path(c)).append('"');
                paint(s, c.fill(), c.stroke(), 1);
                s.append("/>\n");
            } else {
                Text t = (Text) shape;
                s.append("<text x=\"").append(n(t.x())).append("\" y=\"").append(n(t.y())).append("\" font-size=\"")
                        .append(n(t.size())).append('"');
                if (t.anchor() != -1) {
                    s.append(" text-anchor=\"").append(t.anchor() == 0 ? "middle" : "end").append('"');
                }
                if (t.bold()) {
                    s.append(" font-weight=\"bold\"");
                }
                s.append(" fill=\"").append(color(t.color())).append("\">").append(escape(t.text())).append("</text>\n");
            }
        }
        return s.append("</svg>\n").toString();
    }

    /** The SVG path of a sector: outer arc clockwise, inner arc back (or the centre). */
    static String path(Sector c) {
        double sweep = c.to() - c.from();
        if (sweep >= 1 - 1e-9) {
            // a full ring: two half arcs each way, since one arc cannot start and end at one point
            Sector a = new Sector(c.cx(), c.cy(), c.r0(), c.r1(), c.from(), c.from() + 0.5, c.fill(), c.stroke(), c.source());
            Sector b = new Sector(c.cx(), c.cy(), c.r0(), c.r1(), c.from() + 0.5, c.from() + 1 - 1e-6, c.fill(), c.stroke(),
                    c.source());
            return path(a) + " " + path(b);
        }
        int large = sweep > 0.5 ? 1 : 0;
        double[] o0 = onCircle(c.cx(), c.cy(), c.r1(), c.from());
        double[] o1 = onCircle(c.cx(), c.cy(), c.r1(), c.to());
        StringBuilder p = new StringBuilder();
        p.append("M").append(n(o0[0])).append(',').append(n(o0[1])).append(" A").append(n(c.r1())).append(',')
                .append(n(c.r1())).append(" 0 ").append(large).append(",1 ").append(n(o1[0])).append(',').append(n(o1[1]));
        if (c.r0() > 0) {
            double[] i1 = onCircle(c.cx(), c.cy(), c.r0(), c.to());
            double[] i0 = onCircle(c.cx(), c.cy(), c.r0(), c.from());
            p.append(" L").append(n(i1[0])).append(',').append(n(i1[1])).append(" A").append(n(c.r0())).append(',')
                    .append(n(c.r0())).append(" 0 ").append(large).append(",0 ").append(n(i0[0])).append(',').append(n(i0[1]));
        } else {
            p.append(" L").append(n(c.cx())).append(',').append(n(c.cy()));
        }
        return p.append(" Z").toString();
    }

    private static void paint(StringBuilder s, int fill, int stroke, double width) {
        s.append(" fill=\"").append(fill == NONE ? "none" : color(fill)).append('"');
        if (stroke != NONE) {
            s.append(" stroke=\"").append(color(stroke)).append("\" stroke-width=\"").append(n(width)).append('"');
        }
    }

    /** {@code #rrggbb}. */
    public static String color(int rgb) {
        // by hand: String.format took a fifth of the time of a 10 000-module gait diagram
        char[] c = new char[7];
        c[0] = '#';
        for (int i = 0; i < 6; i++) {
            c[6 - i] = Character.forDigit(rgb >> (4 * i) & 0xf, 16);
        }
        return new String(c);
    }

    private static String n(double v) {
        double r = Math.round(v * 100) / 100.0;
        return r == Math.rint(r) ? Long.toString((long) r) : Double.toString(r);
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
