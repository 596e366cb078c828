package org.parpe.gui.panels;

import org.eclipse.swt.graphics.Font;
import org.eclipse.swt.graphics.FontData;
import org.eclipse.swt.widgets.Control;

/**
 * Larger or smaller text for a projector (Ctrl + / Ctrl − / Ctrl 0): a control's font is its
 * normal font grown by 2 points a step. The fonts made here are disposed with their control.
 */
public final class Zoom {
    private static final String KEY = "parpe.zoomFont";

    private Zoom() {
    }

    /** What a key pressed with Ctrl asks for: 1 larger, -1 smaller, 0 the normal size, or {@link #NONE}. */
    public static int step(org.eclipse.swt.widgets.Event e) {
        return e.character == '+' || e.character == '=' || e.keyCode == org.eclipse.swt.SWT.KEYPAD_ADD ? 1
                : e.character == '-' || e.keyCode == org.eclipse.swt.SWT.KEYPAD_SUBTRACT ? -1
                : e.character == '0' || e.keyCode == '0' ? 0 : NONE;
    }

    /** {@link #step} of a key that is not a zoom key. */
    public static final int NONE = Integer.MIN_VALUE;

    /** The zoom after {@code step} ({@link #step}) from {@code steps}: between 4 steps smaller and 12 larger. */
    public static int next(int steps, int step) {
        return step == 0 ? 0 : Math.max(-4, Math.min(12, steps + step));
    }

    /** How many times larger than {@code normal} text is {@code steps} steps in ({@link #apply}'s sizes). */
    public static double factor(Font normal, int steps) {
        int h = normal.getFontData()[0].getHeight();
        return Math.max(6, h + 2 * steps) / (double) Math.max(1, h);
    }

    /** Shows {@code c} in {@code normal} grown by {@code steps} × 2 points (0: {@code normal} itself). */
    public static void apply(Control c, Font normal, int steps) {
        if (c == null || c.isDisposed()) {
            return;
        }
        Font before = (Font) c.getData(KEY);
        Font now = normal;
        if (steps != 0) {
            FontData[] fd = normal.getFontData();
            for (FontData d : fd) {
                d.setHeight(Math.max(6, d.getHeight() + 2 * steps));
            }
            now = new Font(c.getDisplay(), fd);
            if (before == null) {
                c.addListener(org.eclipse.swt.SWT.Dispose, e -> {
                    Font f = (Font) c.getData(KEY);
                    if (f != null) {
                        f.dispose();
                    }
                });
            }
        }
        c.setFont(now);
        c.setData(KEY, steps == 0 ? null : now);
        if (before != null) {
            before.dispose();
        }
        if (c.getParent() != null) {
            c.getParent().layout(true, true);
        }
    }
}
