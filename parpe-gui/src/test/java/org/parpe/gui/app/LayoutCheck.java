package org.parpe.gui.app;

import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CLabel;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.custom.ScrolledComposite;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Group;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Link;
import org.eclipse.swt.widgets.Sash;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.eclipse.swt.widgets.ToolBar;

/**
 * Finds what a user would see cut or covered in a window, whatever language its texts are in
 * (issue 38: "no clipped or overlapping label"): walks a shell's visible widgets and reports, one
 * line each with the widget's text and its path from the shell,
 * <ul>
 * <li>a label, button, {@link CLabel}, link, tool bar or read-only combo smaller than its
 *     preferred size ({@code computeSize(SWT.DEFAULT, SWT.DEFAULT)}; a wrapping label: the height
 *     its text needs at its width);</li>
 * <li>a group whose title is wider than the group, a table column narrower than its header;</li>
 * <li>a tab of a {@link CTabFolder} whose title the folder shortened, or that it moved behind its
 *     chevron;</li>
 * <li>a control that reaches past its parent's client area (cut off by it), except inside a
 *     {@link ScrolledComposite}, which scrolls;</li>
 * <li>two visible siblings that overlap.</li>
 * </ul>
 * Controls hidden on purpose (not visible, or of no size, as an overflow bar hides what does not
 * fit) are not looked at. A label is checked with the text it shows: one that shortens its text
 * to its room on purpose (ending in "…", the whole text its tool tip, as the diagram's live line;
 * decisions.md, "Layouts in the pseudo-language") passes when what it shows fits.
 */
public final class LayoutCheck {
    /** What GTK's cell renderer takes of a column's width beside the text (as ProjectorZoomGuiTest measured). */
    private static final int CELL_MARGIN = 6;
    /** What a GTK frame keeps free beside its title. */
    private static final int GROUP_MARGIN = 8;

    private LayoutCheck() {
    }

    /** Every clipped or overlapping widget of {@code shell}, one line each; empty when all fits. */
    public static List<String> problems(Shell shell) {
        List<String> out = new ArrayList<>();
        walk(shell, "Shell '" + shell.getText() + "'", out);
        return out;
    }

    private static void walk(Control c, String path, List<String> out) {
        clipped(c, path, out);
        if (c instanceof Composite k) {
            Control[] children = k.getChildren();
            List<Control> shown = new ArrayList<>();
            for (int i = 0; i < children.length; i++) {
                Control child = children[i];
                if (!child.getVisible() || child instanceof Shell) {
                    continue;
                }
                Rectangle b = child.getBounds();
                if (b.width <= 0 || b.height <= 0) {
                    continue;
                }
                String childPath = path + " / " + name(child, i);
                outside(k, child, childPath, out);
                for (Control other : shown) {
                    if (!(other instanceof Sash) && !(child instanceof Sash) && other.getBounds().intersects(b)) {
                        out.add("overlaps: " + childPath + " " + b + " covers " + describe(other) + " " + other.getBounds());
                    }
                }
                shown.add(child);
                walk(child, childPath, out);
            }
        }
    }

    /** The widget's class and text, e.g. {@code Button 'Run'}, and its index among its siblings. */
    private static String name(Control c, int index) {
        String t = text(c);
        return c.getClass().getSimpleName() + "#" + index + (t.isEmpty() ? "" : " '" + t + "'");
    }

    private static String describe(Control c) {
        String t = text(c);
        return c.getClass().getSimpleName() + (t.isEmpty() ? "" : " '" + t + "'");
    }

    private static String text(Control c) {
        String t = c instanceof Label l ? l.getText() : c instanceof Button b ? b.getText() : c instanceof CLabel l ? l.getText()
                : c instanceof Link l ? l.getText() : c instanceof Group g ? g.getText() : c instanceof Combo b ? b.getText() : "";
        return t == null ? "" : t;
    }

    /** A control that reaches past the client area of its parent, which cuts it off there. */
    private static void outside(Composite parent, Control child, String path, List<String> out) {
        if (parent instanceof ScrolledComposite || parent instanceof Shell && child instanceof Shell) {
            return;
        }
        Rectangle area = parent.getClientArea();
        Rectangle b = child.getBounds();
        if (b.x < area.x || b.y < area.y || b.x + b.width > area.x + area.width || b.y + b.height > area.y + area.height) {
            out.add("cut off by its parent: " + path + " " + b + " outside " + area);
        }
    }

    private static void clipped(Control c, String path, List<String> out) {
        Rectangle b = c.getBounds();
        if (c instanceof Label || c instanceof Button || c instanceof CLabel || c instanceof Link || c instanceof ToolBar
                || c instanceof Combo && (c.getStyle() & SWT.READ_ONLY) != 0) {
            if (c instanceof Label && (c.getStyle() & SWT.SEPARATOR) != 0 || c instanceof Button && (c.getStyle() & SWT.ARROW) != 0) {
                return;
            }
            boolean wraps = (c.getStyle() & SWT.WRAP) != 0 && !(c instanceof ToolBar);
            Point need = c.computeSize(wraps ? b.width : SWT.DEFAULT, SWT.DEFAULT);
            if (!wraps && b.width < need.x || b.height < need.y) {
                out.add("clipped: " + path + " needs " + need.x + "x" + need.y + ", has " + b.width + "x" + b.height);
            }
        } else if (c instanceof Group g && !g.getText().isEmpty()) {
            int title = extent(g, g.getText());
            if (title + 2 * GROUP_MARGIN > b.width) {
                out.add("clipped title: " + path + " needs " + (title + 2 * GROUP_MARGIN) + " px, has " + b.width);
            }
        } else if (c instanceof Table t && t.getHeaderVisible()) {
            for (TableColumn col : t.getColumns()) {
                int w = extent(t, col.getText()) + CELL_MARGIN;
                if (col.getWidth() > 0 && col.getWidth() < w && !col.getText().isEmpty()) {
                    out.add("clipped header: " + path + " column '" + col.getText() + "' needs " + w + " px, has " + col.getWidth());
                }
            }
        } else if (c instanceof CTabFolder f) {
            tabs(f, path, out);
        }
    }

    private static void tabs(CTabFolder f, String path, List<String> out) {
        for (CTabItem item : f.getItems()) {
            if (!item.isShowing()) {
                out.add("hidden behind the chevron: " + path + " tab '" + item.getText() + "' (folder " + f.getSize().x + " px wide)");
            } else if (shortened(item)) {
                out.add("clipped tab: " + path + " tab '" + item.getText() + "' is " + item.getBounds().width + " px wide");
            }
        }
    }

    /** Whether the folder drew the item's title shortened ("Run l…"): CTabItem keeps the shortened text it drew. */
    private static boolean shortened(CTabItem item) {
        try {
            java.lang.reflect.Field f = CTabItem.class.getDeclaredField("shortenedText");
            f.setAccessible(true);
            Object s = f.get(item);
            return s != null && !s.equals(item.getText());
        } catch (ReflectiveOperationException e) {
            throw new AssertionError("this SWT's CTabItem has no field shortenedText: the check of tab titles needs another way", e);
        }
    }

    private static int extent(Control c, String text) {
        GC gc = new GC(c);
        try {
            gc.setFont(c.getFont());
            return gc.textExtent(text, SWT.DRAW_MNEMONIC).x;
        } finally {
            gc.dispose();
        }
    }
}
