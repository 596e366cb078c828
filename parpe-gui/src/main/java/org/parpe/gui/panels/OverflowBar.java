package org.parpe.gui.panels;

import java.util.ArrayList;
import java.util.List;
import org.eclipse.jface.dialogs.InputDialog;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.RowData;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Layout;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Text;
import org.eclipse.swt.widgets.ToolBar;
import org.eclipse.swt.widgets.ToolItem;
import org.parpe.gui.text.ToolMsg;

/**
 * A row of controls that never runs off its right edge (a 1366-pixel classroom laptop): the
 * controls that do not fit are hidden, and a chevron button (») at the end offers them in a
 * menu, where a button is an item, a check box a check item, a choice a submenu of its values
 * and a text box an item that asks for the text. A label goes with the control after it. The
 * caller creates the controls with {@link #control()} as their parent, in order; a control's
 * {@link RowData} or {@link GridData} width hint is its width. UI thread only.
 */
public final class OverflowBar {
    /** The key under which the bar's composite holds this object ({@code getData}): tests and screenshots. */
    public static final String KEY = "parpe.overflow";
    private static final int SPACING = 4;
    private static final int MARGIN = 3;

    private final Composite bar;
    private final Button chevron;
    private final List<Control> hidden = new ArrayList<>();
    private final java.util.Set<Control> pinned = new java.util.HashSet<>();

    public OverflowBar(Composite parent) {
        bar = new Composite(parent, SWT.NONE);
        bar.setData(KEY, this);
        chevron = new Button(bar, SWT.PUSH);
        chevron.setText("\u00bb");
        chevron.setToolTipText(ToolMsg.PANEL_MORE_TIP.text());
        chevron.addListener(SWT.Selection, e -> {
            Menu m = menu();
            Rectangle b = chevron.getBounds();
            Point at = bar.toDisplay(b.x, b.y + b.height);
            m.setLocation(at);
            m.setVisible(true);
        });
        bar.setLayout(new RowLayout());
    }

    /** The bar: the parent of its controls. */
    public Composite control() {
        return bar;
    }

    /** Keeps {@code c} always in sight (the emergency stop), however narrow the bar; put it first. */
    public void pin(Control c) {
        pinned.add(c);
    }

    /** The controls hidden for want of room, in order. */
    public List<Control> hidden() {
        return List.copyOf(hidden);
    }

    /** Whether the chevron is shown (something did not fit). */
    public boolean overflowing() {
        return chevron.getVisible();
    }

    /** A new menu of the hidden controls, as the chevron shows it (its caller disposes of it when hidden). */
    public Menu menu() {
        Menu m = new Menu(bar.getShell(), SWT.POP_UP);
        m.addListener(SWT.Hide, e -> bar.getDisplay().asyncExec(() -> {
            if (!m.isDisposed()) {
                m.dispose();
            }
        }));
        String label = null;
        for (Control c : hidden) {
            if (c instanceof Label l) {
                label = l.getText().replaceAll(":\\s*$", "");
                continue;
            }
            add(m, c, label);
            label = null;
        }
        return m;
    }

    private static void add(Menu m, Control c, String label) {
        if (c instanceof ToolBar tb) {
            for (ToolItem ti : tb.getItems()) {
                if ((ti.getStyle() & SWT.SEPARATOR) == 0) {
                    item(m, SWT.PUSH, ti.getText(), ti.getEnabled(), () -> ti.notifyListeners(SWT.Selection, new Event()));
                }
            }
        } else if (c instanceof Button b && (b.getStyle() & SWT.CHECK) != 0) {
            MenuItem it = item(m, SWT.CHECK, b.getText(), b.getEnabled(), null);
            it.setSelection(b.getSelection());
            it.addListener(SWT.Selection, e -> {
                b.setSelection(it.getSelection());
                b.notifyListeners(SWT.Selection, new Event());
            });
        } else if (c instanceof Button b) {
            String text = b.getText().equals("\u2026") && b.getToolTipText() != null ? b.getToolTipText() + "\u2026" : b.getText();
            item(m, SWT.PUSH, text, b.getEnabled(), () -> b.notifyListeners(SWT.Selection, new Event()));
        } else if (c instanceof Combo combo && (combo.getStyle() & SWT.READ_ONLY) != 0) {
            MenuItem cascade = item(m, SWT.CASCADE, label != null ? label : combo.getToolTipText(), combo.getEnabled(), null);
            Menu sub = new Menu(cascade);
            cascade.setMenu(sub);
            String[] values = combo.getItems();
            for (int i = 0; i < values.length; i++) {
                int at = i;
                MenuItem v = item(sub, SWT.RADIO, values[i], true, () -> {
                    combo.select(at);
                    combo.notifyListeners(SWT.Selection, new Event());
                });
                v.setSelection(i == combo.getSelectionIndex());
            }
        } else if (c instanceof Combo || c instanceof Text) {
            String name = label != null ? label : ToolMsg.PANEL_VALUE.text();
            item(m, SWT.PUSH, name + ": " + text(c) + "\u2026", c.getEnabled(), () -> {
                InputDialog d = new InputDialog(c.getShell(), name, name + ":", text(c), null);
                if (d.open() == Window.OK) {
                    setText(c, d.getValue());
                }
            });
        }
    }

    private static String text(Control c) {
        return c instanceof Combo combo ? combo.getText() : ((Text) c).getText();
    }

    private static void setText(Control c, String s) {
        if (c instanceof Combo combo) {
            combo.setText(s);
        } else {
            ((Text) c).setText(s);
        }
    }

    private static MenuItem item(Menu m, int style, String text, boolean enabled, Runnable action) {
        MenuItem it = new MenuItem(m, style);
        it.setText(text == null ? "" : text);
        it.setEnabled(enabled);
        if (action != null) {
            it.addListener(SWT.Selection, e -> action.run());
        }
        return it;
    }

    private static Point size(Control c) {
        int w = SWT.DEFAULT;
        if (c.getLayoutData() instanceof RowData rd) {
            w = rd.width;
        } else if (c.getLayoutData() instanceof GridData gd && gd.widthHint != SWT.DEFAULT) {
            w = gd.widthHint;
        }
        return c.computeSize(w, SWT.DEFAULT);
    }

    /** Places the controls left to right; those past the edge are hidden behind the chevron. */
    private final class RowLayout extends Layout {
        @Override
        protected Point computeSize(Composite composite, int wHint, int hHint, boolean flushCache) {
            // The width it needs is what is pinned and the chevron: the rest fits or goes behind the chevron,
            // so the bar never makes its window wider.
            int w = MARGIN;
            int h = 0;
            for (Control c : composite.getChildren()) {
                Point p = size(c);
                h = Math.max(h, p.y);
                if (c == chevron || pinned.contains(c)) {
                    w += p.x + SPACING;
                }
            }
            return new Point(wHint != SWT.DEFAULT ? wHint : w + MARGIN, hHint != SWT.DEFAULT ? hHint : h + 2 * MARGIN);
        }

        @Override
        protected void layout(Composite composite, boolean flushCache) {
            Rectangle area = composite.getClientArea();
            List<Control> items = new ArrayList<>();
            for (Control c : composite.getChildren()) {
                if (c != chevron) {
                    items.add(c);
                }
            }
            int need = MARGIN;
            for (Control c : items) {
                need += size(c).x + SPACING;
            }
            boolean all = need <= area.width;
            Point cs = size(chevron);
            int limit = all ? area.width : area.width - cs.x - SPACING - MARGIN;
            hidden.clear();
            int x = MARGIN;
            boolean full = false;
            for (int i = 0; i < items.size(); i++) {
                Control c = items.get(i);
                Point p = size(c);
                // A label goes with the control it names: both fit, or neither.
                int unit = p.x + (c instanceof Label && i + 1 < items.size() ? SPACING + size(items.get(i + 1)).x : 0);
                full |= !pinned.contains(c) && x + unit > limit;
                if (full) {
                    c.setVisible(false);
                    hidden.add(c);
                    continue;
                }
                c.setVisible(true);
                c.setBounds(x, area.y + Math.max(0, (area.height - p.y) / 2), p.x, p.y);
                x += p.x + SPACING;
            }
            chevron.setVisible(!all);
            if (!all) {
                chevron.setBounds(area.x + area.width - cs.x - MARGIN, area.y + Math.max(0, (area.height - cs.y) / 2), cs.x, cs.y);
            }
        }
    }
}
