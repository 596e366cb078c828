package org.parpe.gui.editor;

import org.parpe.gui.text.UiMsg;
import org.eclipse.jface.dialogs.Dialog;
import org.eclipse.jface.text.IFindReplaceTarget;
import org.eclipse.jface.text.IFindReplaceTargetExtension3;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;

/**
 * A modeless Find/Replace dialog over the editor's {@link IFindReplaceTarget}: find next or
 * previous, replace, replace all, with case and whole-word options; wraps around at the ends.
 */
public final class FindReplaceDialog extends Dialog {
    private final IFindReplaceTarget target;
    private final Runnable refocus;
    private Text find;
    private Text replace;
    private Button caseSensitive;
    private Button wholeWord;
    private Label status;

    public FindReplaceDialog(Shell parent, IFindReplaceTarget target, Runnable refocus) {
        super(parent);
        this.target = target;
        this.refocus = refocus;
        setShellStyle(SWT.DIALOG_TRIM | SWT.MODELESS | SWT.RESIZE);
        setBlockOnOpen(false);
    }

    @Override
    protected void configureShell(Shell shell) {
        super.configureShell(shell);
        shell.setText(UiMsg.FIND_TITLE.text());
    }

    @Override
    protected Control createDialogArea(Composite parent) {
        Composite c = (Composite) super.createDialogArea(parent);
        c.setLayout(new GridLayout(2, false));
        new Label(c, SWT.NONE).setText(UiMsg.FIND_FIND.text());
        find = new Text(c, SWT.BORDER);
        find.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        find.addListener(SWT.DefaultSelection, e -> find(true));
        new Label(c, SWT.NONE).setText(UiMsg.FIND_REPLACE_WITH.text());
        replace = new Text(c, SWT.BORDER);
        replace.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        caseSensitive = new Button(c, SWT.CHECK);
        caseSensitive.setText(UiMsg.FIND_CASE.text());
        wholeWord = new Button(c, SWT.CHECK);
        wholeWord.setText(UiMsg.FIND_WHOLE_WORD.text());
        Composite buttons = new Composite(c, SWT.NONE);
        buttons.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        buttons.setLayout(new GridLayout(5, true));
        button(buttons, UiMsg.FIND_NEXT.text(), () -> find(true));
        button(buttons, UiMsg.FIND_PREVIOUS.text(), () -> find(false));
        button(buttons, UiMsg.BUTTON_REPLACE.text(), this::replaceOne);
        button(buttons, UiMsg.FIND_REPLACE_ALL.text(), this::replaceAll);
        button(buttons, UiMsg.BUTTON_CLOSE.text(), this::close);
        status = new Label(c, SWT.NONE);
        status.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        String sel = target.getSelectionText();
        if (sel != null && !sel.isEmpty() && !sel.contains("\n")) {
            find.setText(sel);
        }
        return c;
    }

    @Override
    protected void createButtonsForButtonBar(Composite parent) {
        // The actions are in the dialog area; no OK/Cancel.
        ((GridLayout) parent.getLayout()).numColumns = 0;
    }

    private static void button(Composite parent, String text, Runnable action) {
        Button b = new Button(parent, SWT.PUSH);
        b.setText(text);
        b.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        b.addListener(SWT.Selection, e -> action.run());
    }

    /** Finds the next match; true if one was selected. */
    boolean find(boolean forward) {
        String what = find.getText();
        if (what.isEmpty()) {
            return false;
        }
        Point sel = target.getSelection();
        int start = forward ? sel.x + sel.y : sel.x - 1;
        int at = findFrom(start, forward, what);
        if (at < 0) {
            at = findFrom(forward ? 0 : Integer.MAX_VALUE / 2, forward, what);
            status.setText(at < 0 ? UiMsg.FIND_NOT_FOUND.text(what) : UiMsg.FIND_WRAPPED.text());
        } else {
            status.setText("");
        }
        refocus.run();
        return at >= 0;
    }

    private int findFrom(int offset, boolean forward, String what) {
        if (target instanceof IFindReplaceTargetExtension3 t3) {
            return t3.findAndSelect(offset, what, forward, caseSensitive.getSelection(), wholeWord.getSelection(), false);
        }
        return target.findAndSelect(offset, what, forward, caseSensitive.getSelection(), wholeWord.getSelection());
    }

    private void replaceOne() {
        String sel = target.getSelectionText();
        boolean matches = caseSensitive.getSelection() ? sel.equals(find.getText()) : sel.equalsIgnoreCase(find.getText());
        if (matches && target.isEditable()) {
            target.replaceSelection(replace.getText());
        }
        find(true);
    }

    private void replaceAll() {
        if (!target.isEditable() || find.getText().isEmpty()) {
            return;
        }
        int n = 0;
        int offset = 0;
        while (true) {
            int at = findFrom(offset, true, find.getText());
            if (at < 0) {
                break;
            }
            target.replaceSelection(replace.getText());
            offset = at + replace.getText().length();
            n++;
        }
        status.setText(UiMsg.FIND_REPLACED.text(n));
    }
}
