package org.parpe.gui.panels;

import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;

/**
 * Widths that a title's language may widen: a table column or a label laid out at a width chosen
 * for English stays at least as wide as its text, which is longer in some languages
 * ("Drehmoment", "So schnell wie möglich").
 */
public final class TitleWidths {
    private TitleWidths() {
    }

    /** A new column of {@code table} titled {@code title}, {@code width} pixels wide or as wide as its title. */
    public static TableColumn column(Table table, int style, String title, int width) {
        TableColumn c = new TableColumn(table, style);
        c.setText(title);
        c.pack(); // no rows yet: as wide as its title
        c.setWidth(Math.max(width, c.getWidth()));
        return c;
    }

    /** Widens {@code label}'s width hint (a {@link GridData}) to its present text where that is wider. */
    public static void label(Label label) {
        GridData gd = (GridData) label.getLayoutData();
        gd.widthHint = Math.max(gd.widthHint, label.computeSize(SWT.DEFAULT, SWT.DEFAULT).x);
    }
}
