package org.parpe.gui.help;

import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;

/**
 * Help → PARSL Quick Reference (F1): {@link HelpText#QUICK_REFERENCE} in a window of its own that
 * can stay open beside the editor, in the fixed-width text font so that its columns line up (a
 * message box set them in a proportional font), and whose text can be selected and copied.
 */
public final class QuickReference {
    private QuickReference() {
    }

    /** Opens the quick reference beside {@code parent}; returns its window. */
    public static Shell open(Shell parent) {
        Shell shell = new Shell(parent, SWT.SHELL_TRIM | SWT.MODELESS);
        shell.setText("PARSL quick reference");
        shell.setLayout(new GridLayout(1, false));
        Text text = new Text(shell, SWT.MULTI | SWT.READ_ONLY | SWT.V_SCROLL | SWT.H_SCROLL | SWT.BORDER);
        text.setFont(JFaceResources.getTextFont());
        text.setText(HelpText.QUICK_REFERENCE);
        text.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        Button close = new Button(shell, SWT.PUSH);
        close.setText("Close");
        close.setLayoutData(new GridData(SWT.END, SWT.CENTER, false, false));
        close.addListener(SWT.Selection, e -> shell.close());
        shell.setDefaultButton(close);
        org.eclipse.swt.graphics.Point size = shell.computeSize(SWT.DEFAULT, SWT.DEFAULT);
        org.eclipse.swt.graphics.Rectangle area = parent.getMonitor().getClientArea();
        shell.setSize(Math.min(size.x + 20, area.width), Math.min(size.y + 20, area.height));
        shell.open();
        return shell;
    }
}
