package org.parpe.gui.diagram;

import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.ScrolledComposite;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Layout;
import org.eclipse.swt.widgets.ScrollBar;

/**
 * The Diagram pane's layout: its controls (choosers, palette, edit row, message, live bar) on
 * top, as tall as they need at the pane's width but never more than half of the pane, and the
 * drawing under them. Where the controls need more (a tab beside the docked tutorial, a longer
 * language: their rows wrap), they scroll, and the drawing keeps at least half the tab (issue 24).
 */
final class AboveTheDrawing extends Layout {
    private static final int MARGIN = 2;
    private static final int GAP = 2;
    private final ScrolledComposite top;
    private final Composite controls;
    private Control drawing;

    private AboveTheDrawing(ScrolledComposite top, Composite controls) {
        this.top = top;
        this.controls = controls;
    }

    /** Lays {@code box} out this way; the controls go into the composite this returns, the drawing after them with {@link #drawing}. */
    static Composite controlsOf(Composite box) {
        ScrolledComposite top = new ScrolledComposite(box, SWT.V_SCROLL);
        top.setExpandHorizontal(true);
        top.setExpandVertical(true);
        Composite controls = new Composite(top, SWT.NONE);
        GridLayout gl = new GridLayout(1, false);
        gl.marginWidth = 0;
        gl.marginHeight = 0;
        gl.verticalSpacing = 2;
        controls.setLayout(gl);
        top.setContent(controls);
        box.setLayout(new AboveTheDrawing(top, controls));
        return controls;
    }

    /** The drawing of {@code box}, laid out by {@link #controlsOf}, under the controls. */
    static void drawing(Composite box, Control drawing) {
        ((AboveTheDrawing) box.getLayout()).drawing = drawing;
    }

    @Override
    protected Point computeSize(Composite box, int wHint, int hHint, boolean flush) {
        int inner = wHint == SWT.DEFAULT ? SWT.DEFAULT : Math.max(0, wHint - 2 * MARGIN);
        Point t = controls.computeSize(inner, SWT.DEFAULT, flush);
        Point d = drawing == null ? new Point(0, 0) : drawing.computeSize(inner, SWT.DEFAULT, flush);
        int w = wHint != SWT.DEFAULT ? wHint : Math.max(t.x, d.x) + 2 * MARGIN;
        int h = hHint != SWT.DEFAULT ? hHint : t.y + GAP + d.y + 2 * MARGIN;
        return new Point(w, h);
    }

    @Override
    protected void layout(Composite box, boolean flush) {
        Rectangle a = box.getClientArea();
        int w = Math.max(0, a.width - 2 * MARGIN);
        int h = Math.max(0, a.height - 2 * MARGIN);
        int need = controls.computeSize(w, SWT.DEFAULT, flush).y;
        // the drawing keeps at least half of the whole pane, margins and gap counted on the controls' side
        int cap = Math.max(0, h - GAP - (a.height + 1) / 2);
        int height = need;
        if (need > cap) {
            ScrollBar bar = top.getVerticalBar();
            need = controls.computeSize(Math.max(0, w - (bar == null ? 0 : bar.getSize().x)), SWT.DEFAULT, flush).y;
            height = cap;
        }
        top.setMinSize(0, need);
        top.setBounds(a.x + MARGIN, a.y + MARGIN, w, height);
        if (drawing != null) {
            drawing.setBounds(a.x + MARGIN, a.y + MARGIN + height + GAP, w, Math.max(0, h - height - GAP));
        }
    }
}
