package org.parpe.gui.help;

import org.parpe.gui.text.UiMsg;
import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.eclipse.swt.widgets.TableItem;

/**
 * Help → PARSL Quick Reference (F1): a window of its own that can stay open beside the editor,
 * with the sections of a program in a real table (section, what it holds, an example in the
 * editor's fixed-width font; a message box had set space-aligned columns in a proportional font),
 * and the keys under it. Rows can be selected and copied with Ctrl+C.
 */
public final class QuickReference {
    private QuickReference() {
    }

    /** Opens the quick reference beside {@code parent}; returns its window. */
    public static Shell open(Shell parent) {
        Shell shell = new Shell(parent, SWT.SHELL_TRIM | SWT.MODELESS);
        shell.setText(UiMsg.QUICK_REFERENCE_TITLE.text());
        shell.setLayout(new GridLayout(1, false));
        Label intro = new Label(shell, SWT.WRAP);
        intro.setText(HelpText.notes()[0]);
        Table table = new Table(shell, SWT.BORDER | SWT.FULL_SELECTION | SWT.MULTI);
        table.setHeaderVisible(true);
        table.setLinesVisible(true);
        table.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        for (String h : new String[] {UiMsg.COLUMN_SECTION.text(), UiMsg.COLUMN_HOLDS.text(), UiMsg.COLUMN_EXAMPLE.text()}) {
            new TableColumn(table, SWT.LEFT).setText(h);
        }
        for (String[] row : HelpText.sections()) {
            TableItem item = new TableItem(table, SWT.NONE);
            item.setText(row);
            item.setFont(0, JFaceResources.getTextFont());
            item.setFont(2, JFaceResources.getTextFont());
        }
        fitColumns(table);
        table.addListener(SWT.KeyDown, e -> {
            if ((e.stateMask & SWT.MOD1) != 0 && (e.keyCode == 'c' || e.keyCode == SWT.INSERT)) {
                copySelection(table);
            }
        });
        String[] notes = HelpText.notes();
        for (int i = 1; i < notes.length; i++) {
            new Label(shell, SWT.WRAP).setText(notes[i]);
        }
        Button close = new Button(shell, SWT.PUSH);
        close.setText(org.eclipse.jface.dialogs.IDialogConstants.CLOSE_LABEL);
        close.setLayoutData(new GridData(SWT.END, SWT.CENTER, false, false));
        close.addListener(SWT.Selection, e -> shell.close());
        shell.setDefaultButton(close);
        org.eclipse.swt.graphics.Point size = shell.computeSize(SWT.DEFAULT, SWT.DEFAULT);
        org.eclipse.swt.graphics.Rectangle area = parent.getMonitor().getClientArea();
        shell.setSize(Math.min(size.x + 20, area.width), Math.min(size.y + 20, area.height));
        shell.open();
        return shell;
    }

    /** Each column as wide as its widest cell in that cell's font (pack() measures the table's font only). */
    private static void fitColumns(Table table) {
        org.eclipse.swt.graphics.GC gc = new org.eclipse.swt.graphics.GC(table);
        try {
            for (int c = 0; c < table.getColumnCount(); c++) {
                TableColumn column = table.getColumn(c);
                column.pack();
                int width = column.getWidth();
                for (TableItem item : table.getItems()) {
                    gc.setFont(item.getFont(c));
                    width = Math.max(width, gc.textExtent(item.getText(c)).x + 24);
                }
                column.setWidth(width);
            }
        } finally {
            gc.dispose();
        }
    }

    /** Puts the selected rows on the clipboard, a tab between cells. */
    private static void copySelection(Table table) {
        StringBuilder b = new StringBuilder();
        for (TableItem item : table.getSelection()) {
            b.append(item.getText(0)).append('\t').append(item.getText(1)).append('\t').append(item.getText(2)).append('\n');
        }
        org.eclipse.swt.dnd.Clipboard clip = new org.eclipse.swt.dnd.Clipboard(table.getDisplay());
        clip.setContents(new Object[] {b.toString()}, new org.eclipse.swt.dnd.Transfer[] {org.eclipse.swt.dnd.TextTransfer.getInstance()});
        clip.dispose();
    }
}
