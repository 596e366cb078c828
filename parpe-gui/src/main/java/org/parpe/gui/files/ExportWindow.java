package org.parpe.gui.files;

import org.parpe.gui.text.UiMsg;
import java.nio.file.Path;
import java.util.List;
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
    private FileActions.Questions questions;

    ExportWindow(Shell parent, String title) {
        shell = new Shell(parent, SWT.DIALOG_TRIM | SWT.RESIZE | SWT.MODELESS);
        shell.setText(title);
        shell.setLayout(new GridLayout(3, false));
        questions = (t, text, buttons) -> new org.eclipse.jface.dialogs.MessageDialog(shell, t, null, text,
                org.eclipse.jface.dialogs.MessageDialog.QUESTION, buttons, 1).open();
    }

    /** Answers this window's questions with {@code q} instead of dialogs (tests). */
    void answerWith(FileActions.Questions q) {
        questions = q;
    }

    /** The files of {@code names} that are in {@code dir} already. */
    static List<Path> existing(Path dir, java.util.Collection<String> names) {
        return names.stream().map(dir::resolve).filter(java.nio.file.Files::exists).toList();
    }

    /**
     * UI thread: whether the export of {@code what} may replace {@code taken}, files in {@code dir}
     * that are the user's (an earlier export, perhaps edited since): asked when there are any, and
     * on Cancel the message says they are kept. The CLI's {@code --out} names its folder on purpose
     * and replaces them (docs/cli.md, output rules).
     */
    boolean mayReplace(Path dir, List<Path> taken, String what) {
        if (taken.isEmpty()) {
            return true;
        }
        String files = taken.stream().map(p -> p.getFileName().toString()).collect(java.util.stream.Collectors.joining(", "));
        boolean one = taken.size() == 1;
        if (questions.ask((one ? UiMsg.REPLACE_FILE_TITLE : UiMsg.REPLACE_FILES_TITLE).text(),
                (one ? UiMsg.REPLACE_IT : UiMsg.REPLACE_THEM).text(dir, files, what), UiMsg.BUTTON_REPLACE.text(),
                org.eclipse.jface.dialogs.IDialogConstants.CANCEL_LABEL) == 0) {
            return true;
        }
        say(UiMsg.NOTHING_WRITTEN.text((one ? UiMsg.FILE_KEPT : UiMsg.FILES_KEPT).text(
                taken.stream().map(Path::toString).collect(java.util.stream.Collectors.joining(", ")))));
        return false;
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
        label(UiMsg.EXPORT_FOLDER.text());
        folder = new Text(shell, SWT.BORDER);
        folder.setText(FileDialogs.start().resolve(name).toString());
        GridData fd = new GridData(SWT.FILL, SWT.CENTER, true, false);
        fd.widthHint = 420;
        folder.setLayoutData(fd);
        button(UiMsg.EXPORT_BROWSE.text(), () -> askFolder(browse));
        message = new Text(shell, SWT.MULTI | SWT.READ_ONLY | SWT.WRAP | SWT.V_SCROLL | SWT.BORDER);
        GridData md = new GridData(SWT.FILL, SWT.FILL, true, true, 3, 1);
        md.heightHint = height;
        message.setLayoutData(md);
        new Label(shell, SWT.NONE).setLayoutData(span());
        export = button(UiMsg.EXPORT_BUTTON.text(), action);
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
        d.setText(UiMsg.EXPORT_INTO.text());
        d.setMessage(what);
        d.setFilterPath(FileDialogs.start().toString());
        String chosen = d.open();
        if (chosen != null) {
            folder.setText(chosen);
        }
    }
}
