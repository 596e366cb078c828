package org.parpe.gui.panels;

import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.PaletteData;
import org.eclipse.swt.widgets.Display;

/**
 * The IDE's small icons, drawn at start-up (no image files, no font glyphs that a machine may
 * lack). Owned by the display: disposed with it.
 */
public final class Icons {
    private static final int SIZE = 16;

    /** Run: a green triangle. */
    public final Image run;
    /** Pause: two bars. */
    public final Image pause;
    /** Stop: a square. */
    public final Image stop;
    /** Emergency stop: a red octagon. */
    public final Image estop;
    /** Error: a red disc with an exclamation mark. */
    public final Image error;
    /** Warning: an amber triangle. */
    public final Image warning;

    private Icons(Display d) {
        run = draw(d, (gc, c) -> {
            gc.setBackground(c.apply(0x2E9E44));
            gc.fillPolygon(new int[] {4, 2, 14, 8, 4, 14});
        });
        pause = draw(d, (gc, c) -> {
            gc.setBackground(c.apply(0x3A5A8C));
            gc.fillRectangle(3, 3, 4, 11);
            gc.fillRectangle(9, 3, 4, 11);
        });
        stop = draw(d, (gc, c) -> {
            gc.setBackground(c.apply(0x44484F));
            gc.fillRectangle(3, 3, 10, 10);
        });
        estop = draw(d, (gc, c) -> {
            gc.setBackground(c.apply(0xD02121));
            gc.fillPolygon(new int[] {5, 0, 11, 0, 16, 5, 16, 11, 11, 16, 5, 16, 0, 11, 0, 5});
            gc.setBackground(c.apply(0xFFFFFF));
            gc.fillRectangle(3, 7, 10, 3);
        });
        error = draw(d, (gc, c) -> {
            gc.setBackground(c.apply(0xD02121));
            gc.fillOval(1, 1, 14, 14);
            gc.setBackground(c.apply(0xFFFFFF));
            gc.fillRectangle(7, 4, 2, 6);
            gc.fillRectangle(7, 11, 2, 2);
        });
        warning = draw(d, (gc, c) -> {
            gc.setBackground(c.apply(0xE09A10));
            gc.fillPolygon(new int[] {8, 1, 15, 15, 1, 15});
            gc.setBackground(c.apply(0xFFFFFF));
            gc.fillRectangle(7, 6, 2, 5);
            gc.fillRectangle(7, 12, 2, 2);
        });
    }

    /** The icons of {@code display}, made on first use. */
    public static Icons of(Display display) {
        Object o = display.getData(Icons.class.getName());
        if (o instanceof Icons icons) {
            return icons;
        }
        Icons icons = new Icons(display);
        display.setData(Icons.class.getName(), icons);
        display.disposeExec(icons::dispose);
        return icons;
    }

    private interface Painter {
        void paint(GC gc, java.util.function.IntFunction<Color> color);
    }

    private static Image draw(Display d, Painter p) {
        ImageData data = new ImageData(SIZE, SIZE, 32, new PaletteData(0xFF0000, 0xFF00, 0xFF));
        data.alphaData = new byte[SIZE * SIZE];
        Image mask = new Image(d, data);
        GC gc = new GC(mask);
        gc.setAntialias(SWT.ON);
        p.paint(gc, rgb -> new Color((rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF));
        gc.dispose();
        ImageData drawn = mask.getImageData();
        mask.dispose();
        // Transparent wherever nothing was painted: paint the same shapes into an alpha channel.
        ImageData alpha = new ImageData(SIZE, SIZE, 32, new PaletteData(0xFF0000, 0xFF00, 0xFF));
        Image a = new Image(d, alpha);
        GC ga = new GC(a);
        ga.setBackground(d.getSystemColor(SWT.COLOR_BLACK));
        ga.fillRectangle(0, 0, SIZE, SIZE);
        ga.setAntialias(SWT.ON);
        p.paint(ga, rgb -> d.getSystemColor(SWT.COLOR_WHITE));
        ga.dispose();
        ImageData ad = a.getImageData();
        a.dispose();
        byte[] alphas = new byte[SIZE * SIZE];
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                alphas[y * SIZE + x] = (byte) (ad.palette.getRGB(ad.getPixel(x, y)).red);
            }
        }
        drawn.alphaData = alphas;
        return new Image(d, drawn);
    }

    private void dispose() {
        for (Image i : new Image[] {run, pause, stop, estop, error, warning}) {
            i.dispose();
        }
    }
}
