package org.parpe.gui.panels;

import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.RGB;
import org.eclipse.swt.widgets.Display;

/**
 * The IDE's own colours taken from the GTK theme: with a dark theme (GTK_THEME=Adwaita:dark, a
 * projector's high-contrast setting) the editor's syntax colours, the current line, the tabs, the
 * table's tints and the plots' paper follow it instead of staying light (dark blue on dark grey,
 * white text on a white line). Every colour of the IDE that is not the theme's own comes from here.
 */
public final class Theme {
    private static Boolean dark;

    private Theme() {
    }

    /** Whether the theme's text fields are dark (their background darker than mid grey). */
    public static boolean dark() {
        if (dark == null) {
            RGB bg = Display.getDefault().getSystemColor(SWT.COLOR_LIST_BACKGROUND).getRGB();
            dark = 0.2126 * bg.red + 0.7152 * bg.green + 0.0722 * bg.blue < 128;
        }
        return dark;
    }

    /** {@code light} (0xRRGGBB) with a light theme, {@code darkRgb} with a dark one. */
    public static Color pick(int light, int darkRgb) {
        int c = dark() ? darkRgb : light;
        return new Color((c >> 16) & 0xFF, (c >> 8) & 0xFF, c & 0xFF);
    }

    /** The paper of a plot: the theme's text-field background. */
    public static Color paper() {
        return Display.getDefault().getSystemColor(SWT.COLOR_LIST_BACKGROUND);
    }

    /** Text and frames on a plot's paper: the theme's text colour. */
    public static Color ink() {
        return Display.getDefault().getSystemColor(SWT.COLOR_LIST_FOREGROUND);
    }

    /**
     * Colour {@code rgb} of a drawing made for white paper (the diagrams), on the theme's paper:
     * itself with a light theme; with a dark one white becomes the paper and every other colour
     * has its lightness turned over, its hue kept (dark ink light, a pale fill deep), so that the
     * drawing is not a white sheet on a dark window.
     */
    public static int onPaper(int rgb) {
        if (!dark()) {
            return rgb;
        }
        if (rgb == 0xffffff) {
            RGB p = paper().getRGB();
            return p.red << 16 | p.green << 8 | p.blue;
        }
        int r = rgb >> 16 & 0xff;
        int g = rgb >> 8 & 0xff;
        int b = rgb & 0xff;
        int turn = 255 - Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b));
        return (turn + r) << 16 | (turn + g) << 8 | (turn + b);
    }

    /** Gridlines on a plot's paper: between paper and ink. */
    public static Color faint() {
        return dark() ? pick(0, 0x555555) : Display.getDefault().getSystemColor(SWT.COLOR_GRAY);
    }
}
