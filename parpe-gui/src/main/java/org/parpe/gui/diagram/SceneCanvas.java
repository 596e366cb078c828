package org.parpe.gui.diagram;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.Font;
import org.eclipse.swt.graphics.FontData;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.Path;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.graphics.Transform;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Composite;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diagram.Scene;
import org.parpe.gui.panels.Theme;

/**
 * Draws a {@link Scene} with SWT, as the SVG and PNG back ends draw it for files, scaled down to
 * fit the canvas (never up) and centred, its empty bottom left out and no text smaller than
 * {@link #MIN_TEXT_PX} on screen (so that a short canvas still has readable labels; the window's
 * zoom makes that floor larger); the shapes that stand for a place in the script are
 * what a click hits, and the selected place is outlined. UI thread only.
 */
final class SceneCanvas {
    /** The outline of the selected node. */
    static final int SELECTION = 0x1f6fd0;

    /** The smallest text on screen, in pixels: a scene scaled far down keeps its labels this large. */
    static final double MIN_TEXT_PX = 9;
    /** Scene units below the lowest shape kept in view: room for the marks of the live overlay (breakpoints: 25). */
    private static final double BELOW = 30;

    private final Canvas canvas;
    /** How tall the part of the scene with shapes in it is (from its top), in scene units. */
    private double used = 1;
    /** The size of text that is {@link #MIN_TEXT_PX} on screen at the scale drawn, in scene units. */
    private double textFloor;
    private final Map<Integer, Color> colors = new HashMap<>();
    private final Map<Long, Font> fonts = new HashMap<>();
    private Scene scene = new Scene(1, 1);
    private SourcePos selected;
    private List<Scene.Shape> overlay = List.of();
    private long paints;
    /** The window's zoom: the smallest text is {@link #MIN_TEXT_PX} times this. */
    private double zoom = 1;
    /** Where the scene's texts were drawn last, in canvas pixels, with their text. */
    private final List<Map.Entry<Rectangle, String>> drawnTexts = new ArrayList<>();
    private boolean recording;
    /** The scene and the selection drawn once, so that a frame of the live overlay draws only the overlay over it. */
    private Image cache;

    /** A canvas in {@code parent}; {@code clicked} learns the place under a left click (or {@code null}). */
    SceneCanvas(Composite parent, Consumer<SourcePos> clicked) {
        canvas = new Canvas(parent, SWT.DOUBLE_BUFFERED | SWT.NO_BACKGROUND);
        canvas.addListener(SWT.Paint, e -> paint(e.gc));
        canvas.addListener(SWT.MouseDown, e -> {
            if (e.button == 1) {
                double[] p = toScene(e.x, e.y);
                clicked.accept(hit(p[0], p[1]));
            }
        });
        canvas.addListener(SWT.Resize, e -> {
            dropCache();
            canvas.redraw();
        });
        canvas.addListener(SWT.Dispose, e -> {
            dropCache();
            colors.values().forEach(Color::dispose);
            fonts.values().forEach(Font::dispose);
        });
    }

    Canvas control() {
        return canvas;
    }

    /** Shows {@code s}. */
    void show(Scene s) {
        scene = s;
        used = used(s);
        overlay = List.of();
        dropCache();
        canvas.redraw();
    }

    /** Scene units to canvas pixels: {@code {scale, dx, dy}}, the scene fitted in and centred. */
    private double[] fit() {
        Rectangle a = canvas.getClientArea();
        double k = scale(scene, used);
        return new double[] {k, Math.max(0, (a.width - scene.width() * k) / 2), 0};
    }

    /** The scale {@code s} is drawn at on the canvas as it is now, {@code used} of its height shown. */
    private double scale(Scene s, double used) {
        Rectangle a = canvas.getClientArea();
        double k = Math.min(1, Math.min(a.width / (double) s.width(), a.height / used));
        return k > 0 ? k : 1;
    }

    /**
     * How many times larger than {@code size} text of {@code s} must be made so that, drawn on the
     * canvas as it is now, it is {@link #MIN_TEXT_PX} high, zoomed, or more (at least 1).
     */
    double textScale(Scene s, double size) {
        return Math.max(1, MIN_TEXT_PX * zoom / (size * scale(s, used(s))));
    }

    /** Makes the smallest text on screen {@code factor} times {@link #MIN_TEXT_PX} (the window's zoom). */
    void zoom(double factor) {
        zoom = factor;
        dropCache();
        canvas.redraw();
    }

    /** The height of {@code s} down to its lowest shape and {@link #BELOW} more, at most its own height. */
    private static double used(Scene s) {
        double bottom = 0;
        for (Scene.Shape shape : s.shapes()) {
            bottom = Math.max(bottom, shape instanceof Scene.Rect r ? r.y() + r.h()
                    : shape instanceof Scene.Line l ? Math.max(l.y1(), l.y2())
                    : shape instanceof Scene.Sector c ? c.cy() + c.r1()
                    : ((Scene.Text) shape).y() + ((Scene.Text) shape).size() / 2);
        }
        return Math.max(1, Math.min(s.height(), bottom + BELOW));
    }

    /** The scene point under canvas pixel {@code x, y}. */
    double[] toScene(int x, int y) {
        double[] f = fit();
        return new double[] {(x - f[1]) / f[0], (y - f[2]) / f[0]};
    }

    /** The canvas pixel of scene point {@code x, y}. */
    Point toCanvas(double x, double y) {
        double[] f = fit();
        return new Point((int) Math.round(x * f[0] + f[1]), (int) Math.round(y * f[0] + f[2]));
    }

    Scene scene() {
        return scene;
    }

    /** Draws {@code shapes} over the scene (the live overlay); empty for none. */
    void overlay(List<Scene.Shape> shapes) {
        overlay = List.copyOf(shapes);
        canvas.redraw();
    }

    /** The shapes drawn over the scene now ({@link #overlay}). */
    List<Scene.Shape> overlaid() {
        return overlay;
    }

    /** Outlines the shapes of {@code node} ({@code null}: none). */
    void select(SourcePos node) {
        selected = node;
        dropCache();
        canvas.redraw();
    }

    /** The place of the topmost shape at scene point {@code x, y} that stands for one, or {@code null}. */
    SourcePos hit(double x, double y) {
        List<Scene.Shape> shapes = scene.shapes();
        for (int i = shapes.size() - 1; i >= 0; i--) {
            Scene.Shape s = shapes.get(i);
            if (s instanceof Scene.Rect r && r.source() != null && x >= r.x() && x <= r.x() + r.w() && y >= r.y()
                    && y <= r.y() + r.h()) {
                return r.source();
            }
            if (s instanceof Scene.Sector c && c.source() != null && inside(c, x, y)) {
                return c.source();
            }
        }
        return null;
    }

    /** Where on the canvas the first shape of {@code node} is, or {@code null}: a click there selects it. */
    Point centre(SourcePos node) {
        double[] at = at(node);
        return at == null ? null : toCanvas(at[0], at[1]);
    }

    private double[] at(SourcePos node) {
        for (Scene.Shape s : scene.shapes()) {
            if (s instanceof Scene.Rect r && node.equals(r.source())) {
                return new double[] {r.x() + Math.min(r.w() / 2, 20), r.y() + r.h() / 2};
            }
            if (s instanceof Scene.Sector c && node.equals(c.source())) {
                double[] p = Scene.onCircle(c.cx(), c.cy(), (c.r0() + c.r1()) / 2, (c.from() + c.to()) / 2);
                return p;
            }
        }
        return null;
    }

    private static boolean inside(Scene.Sector c, double x, double y) {
        double dx = x - c.cx();
        double dy = y - c.cy();
        double r = Math.hypot(dx, dy);
        if (r < c.r0() || r > c.r1()) {
            return false;
        }
        // fraction of a turn, 0 at the top, clockwise (as Scene.onCircle)
        double f = Math.atan2(dx, -dy) / (2 * Math.PI);
        f = f < 0 ? f + 1 : f;
        return f >= c.from() && f <= c.to();
    }

    /** How many times the canvas was painted (for the benchmark). */
    long paints() {
        return paints;
    }

    private void dropCache() {
        if (cache != null) {
            cache.dispose();
            cache = null;
        }
    }

    private void paint(GC gc) {
        paints++;
        Rectangle area = canvas.getClientArea();
        if (area.width <= 0 || area.height <= 0) {
            return;
        }
        if (cache == null) {
            cache = new Image(canvas.getDisplay(), area.width, area.height);
            GC image = new GC(cache);
            try {
                image.setBackground(color(0xffffff));
                image.fillRectangle(0, 0, area.width, area.height);
                drawnTexts.clear();
                recording = true;
                transformed(image, g -> {
                    draw(g, scene.shapes());
                    outline(g);
                });
                recording = false;
            } finally {
                image.dispose();
            }
        }
        gc.drawImage(cache, 0, 0);
        if (!overlay.isEmpty()) {
            transformed(gc, g -> draw(g, overlay));
        }
    }

    /** Runs {@code draw} on {@code gc} in scene units (the scene fitted in and centred), antialiased. */
    private void transformed(GC gc, Consumer<GC> draw) {
        gc.setAdvanced(true);
        gc.setAntialias(SWT.ON);
        gc.setTextAntialias(SWT.ON);
        double[] f = fit();
        Transform t = new Transform(canvas.getDisplay(),
                (float) f[0], 0, 0, (float) f[0], (float) f[1], (float) f[2]);
        try {
            gc.setTransform(t);
            textFloor = MIN_TEXT_PX * zoom / f[0];
            draw.accept(gc);
        } finally {
            gc.setTransform(null);
            t.dispose();
        }
    }

    private void draw(GC gc, List<Scene.Shape> shapes) {
        for (Scene.Shape s : shapes) {
            if (s instanceof Scene.Rect r) {
                rect(gc, r);
            } else if (s instanceof Scene.Line l) {
                gc.setForeground(color(l.stroke()));
                gc.setLineWidth((int) Math.max(1, Math.round(l.width())));
                gc.setLineStyle(l.dash() > 0 ? SWT.LINE_DASH : SWT.LINE_SOLID);
                gc.drawLine((int) Math.round(l.x1()), (int) Math.round(l.y1()), (int) Math.round(l.x2()),
                        (int) Math.round(l.y2()));
                gc.setLineStyle(SWT.LINE_SOLID);
            } else if (s instanceof Scene.Sector c) {
                sector(gc, c, c.fill(), c.stroke(), 1);
            } else {
                text(gc, (Scene.Text) s);
            }
        }
    }

    private void outline(GC gc) {
        if (selected != null) {
            for (Scene.Shape s : scene.shapes()) {
                if (s instanceof Scene.Rect r && selected.equals(r.source())) {
                    gc.setForeground(color(SELECTION));
                    gc.setLineWidth(3);
                    gc.drawRectangle((int) r.x() - 2, (int) r.y() - 2, (int) r.w() + 4, (int) r.h() + 4);
                } else if (s instanceof Scene.Sector c && selected.equals(c.source())) {
                    sector(gc, c, Scene.NONE, SELECTION, 3);
                }
            }
        }
    }

    private void rect(GC gc, Scene.Rect r) {
        int x = (int) Math.round(r.x());
        int y = (int) Math.round(r.y());
        int w = (int) Math.round(r.w());
        int h = (int) Math.round(r.h());
        if (r.fill() != Scene.NONE) {
            gc.setBackground(color(r.fill()));
            gc.fillRectangle(x, y, w, h);
        }
        if (r.stroke() != Scene.NONE) {
            gc.setForeground(color(r.stroke()));
            gc.setLineWidth((int) Math.max(1, Math.round(r.strokeWidth())));
            gc.drawRectangle(x, y, w, h);
        }
    }

    /** SWT measures arcs in degrees counter-clockwise from 3 o'clock; the scene in turns clockwise from the top. */
    private void sector(GC gc, Scene.Sector c, int fill, int stroke, int width) {
        float start = (float) (90 - c.from() * 360);
        float extent = (float) (-(c.to() - c.from()) * 360);
        Path p = new Path(gc.getDevice());
        try {
            float r1 = (float) c.r1();
            p.addArc((float) (c.cx() - r1), (float) (c.cy() - r1), 2 * r1, 2 * r1, start, extent);
            if (c.r0() > 0) {
                float r0 = (float) c.r0();
                p.addArc((float) (c.cx() - r0), (float) (c.cy() - r0), 2 * r0, 2 * r0, start + extent, -extent);
            } else {
                p.lineTo((float) c.cx(), (float) c.cy());
            }
            p.close();
            if (fill != Scene.NONE) {
                gc.setBackground(color(fill));
                gc.fillPath(p);
            }
            if (stroke != Scene.NONE) {
                gc.setForeground(color(stroke));
                gc.setLineWidth(width);
                gc.drawPath(p);
            }
        } finally {
            p.dispose();
        }
    }

    private void text(GC gc, Scene.Text t) {
        gc.setFont(font(Math.max(t.size(), textFloor), t.bold()));
        gc.setForeground(color(t.color()));
        Point size = gc.textExtent(t.text(), SWT.DRAW_TRANSPARENT);
        double x = t.anchor() < 0 ? t.x() : t.anchor() == 0 ? t.x() - size.x / 2.0 : t.x() - size.x;
        int ascent = gc.getFontMetrics().getAscent();
        gc.drawText(t.text(), (int) Math.round(x), (int) Math.round(t.y()) - ascent, SWT.DRAW_TRANSPARENT);
        if (recording) {
            Point a = toCanvas(x, Math.round(t.y()) - ascent);
            Point b = toCanvas(x + size.x, Math.round(t.y()) - ascent + size.y);
            drawnTexts.add(Map.entry(new Rectangle(a.x, a.y, b.x - a.x, b.y - a.y), t.text()));
        }
    }

    /** The scene's texts as last painted: where on the canvas (pixels) each one's extent went, and its text. */
    List<Map.Entry<Rectangle, String>> drawnTexts() {
        return List.copyOf(drawnTexts);
    }

    private Color color(int rgb) {
        // the scene's colours are for white paper; a dark theme turns them over (Theme.onPaper)
        return colors.computeIfAbsent(rgb, k -> {
            int c = Theme.onPaper(k);
            return new Color(c >> 16 & 0xff, c >> 8 & 0xff, c & 0xff);
        });
    }

    /** A font whose em is {@code px} pixels (SWT sizes fonts in points). */
    private Font font(double px, boolean bold) {
        int dpi = canvas.getDisplay().getDPI().y;
        int points = (int) Math.max(6, Math.round(px * 72 / Math.max(72, dpi)));
        long key = points * 2L + (bold ? 1 : 0);
        return fonts.computeIfAbsent(key, k -> {
            FontData d = canvas.getDisplay().getSystemFont().getFontData()[0];
            return new Font(canvas.getDisplay(), d.getName(), points, bold ? SWT.BOLD : SWT.NORMAL);
        });
    }
}
