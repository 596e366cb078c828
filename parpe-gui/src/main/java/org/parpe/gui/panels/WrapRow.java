package org.parpe.gui.panels;

import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.RowLayout;
import org.eclipse.swt.widgets.Composite;

/**
 * A row of controls that wraps onto a second line only when its pane is too narrow for it (a
 * longer language, a docked tutorial beside it, a 1366-pixel laptop), instead of cutting off what
 * does not fit. Controls in it take {@link org.eclipse.swt.layout.RowData}, not {@code GridData}.
 */
public final class WrapRow {
    private WrapRow() {
    }

    /** The layout: left to right, centred on the line, wrapping, with little margin. */
    public static RowLayout layout() {
        RowLayout rl = new RowLayout(SWT.HORIZONTAL);
        rl.wrap = true;
        rl.center = true;
        rl.marginTop = 0;
        rl.marginBottom = 0;
        rl.marginLeft = 0;
        rl.marginRight = 0;
        rl.spacing = 3;
        return rl;
    }

    /** A new row in {@code parent} (whose layout is a {@code GridLayout}) that takes its width and wraps in it. */
    public static Composite of(Composite parent) {
        Composite c = new Composite(parent, SWT.NONE);
        c.setLayout(layout());
        c.setLayoutData(new GridData(SWT.FILL, SWT.TOP, true, false));
        return c;
    }
}
