package org.parpe.gui.files;

import java.nio.file.Path;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.DirectoryDialog;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.panels.FileDialogs;

/**
 * What the IDE's export windows (File → Export Robot…, File → Export Program as C/Arduino…)
 * share: a window beside the IDE (not modal) of labelled rows, the folder to write into with
 * Browse…, the message that says what was written or why nothing was, and Export. UI thread only.
 */
final class ExportWindow {
    private final Shell shell;
    private Text folder;
    private Text message;
    private Button export;

    ExportWindow(Shell parent, String title) {
        shell = new Shell(parent, SWT.DIALOG_TRIM | SWT.RESIZE | SWT.MODELESS);
        shell.setText(title);
        shell.setLayout(new GridLayout(3, false));
    }

    Shell shell() {
        return shell;
    }

    /** Starts a row with {@code label}; its control spans the other two columns ({@link #span()}). */
    void label(String label) {
        new Label(shell, SWT.NONE).setText(label);
    }

    /** Layout data for a row's control. */
    static GridData span() {
        return new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1);
    }

    /** A row of {@code label} and a read-only choice of {@code items}, the first chosen. */
    Combo combo(String label, String[] items) {
        label(label);
        Combo c = new Combo(shell, SWT.READ_ONLY);
        for (String s : items) {
            c.add(s);
        }
        c.select(0);
        c.setLayoutData(span());
        return c;
    }

    /**
     * The last rows: the folder (starting on {@code name} in the file dialogs' start folder;
     * {@code browse} says in Browse… what it is for), the message ({@code height} pixels high) and
     * Export, which runs {@code action}.
     */
    void finish(String name, String browse, int height, Runnable action) {
        label("Folder:");
        folder = new Text(shell, SWT.BORDER);
        folder.setText(FileDialogs.start().resolve(name).toString());
        GridData fd = new GridData(SWT.FILL, SWT.CENTER, true, false);
        fd.widthHint = 420;
        folder.setLayoutData(fd);
        button("Browse\u2026", () -> askFolder(browse));
        message = new Text(shell, SWT.MULTI | SWT.READ_ONLY | SWT.WRAP | SWT.V_SCROLL | SWT.BORDER);
        GridData md = new GridData(SWT.FILL, SWT.FILL, true, true, 3, 1);
        md.heightHint = height;
        message.setLayoutData(md);
        new Label(shell, SWT.NONE).setLayoutData(span());
        export = button("Export", action);
        shell.setDefaultButton(export);
    }

    /** Sizes the window and opens it over the middle of {@code parent}'s upper part. */
    void open(Shell parent) {
        shell.pack();
        Rectangle over = parent.getBounds();
        Point size = shell.getSize();
        shell.setLocation(over.x + Math.max(0, (over.width - size.x) / 2), over.y + Math.max(0, (over.height - size.y) / 3));
        shell.open();
    }

    /** The folder chosen, absolute. */
    Path folder() {
        return Path.of(folder.getText().trim()).toAbsolutePath();
    }

    void setFolder(Path dir) {
        folder.setText(dir.toString());
    }

    String message() {
        return message.getText();
    }

    /** Shows {@code text} as what happened. */
    void say(String text) {
        message.setText(text);
    }

    /** While an export is written, Export is off. */
    void exporting(boolean busy) {
        export.setEnabled(!busy);
    }

    private Button button(String text, Runnable action) {
        Button b = new Button(shell, SWT.PUSH);
        b.setText(text);
        b.addListener(SWT.Selection, e -> action.run());
        return b;
    }

    private void askFolder(String what) {
        DirectoryDialog d = new DirectoryDialog(shell);
        d.setText("Export Into");
        d.setMessage(what);
        d.setFilterPath(FileDialogs.start().toString());
        String chosen = d.open();
        if (chosen != null) {
            folder.setText(chosen);
        }
    }
}
