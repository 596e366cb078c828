package org.parpe.gui.app;

import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;

/**
 * A white-on-red strip across the window under the tool bar, shown only while something needs
 * the user at once (the robot stopped answering during a hardware run) and gone otherwise: the
 * status bar's red field alone is easy to miss from across a classroom.
 */
final class AlarmBanner {
    private final Label label;
    private final GridData data;

    AlarmBanner(Composite parent) {
        label = new Label(parent, SWT.CENTER);
        label.setBackground(parent.getDisplay().getSystemColor(SWT.COLOR_RED));
        label.setForeground(parent.getDisplay().getSystemColor(SWT.COLOR_WHITE));
        var font = label.getFont().getFontData()[0];
        var bold = new org.eclipse.swt.graphics.Font(parent.getDisplay(), font.getName(),
                Math.round(font.getHeight() * 1.25f), SWT.BOLD);
        label.setFont(bold);
        label.addDisposeListener(e -> bold.dispose());
        data = new GridData(SWT.FILL, SWT.CENTER, true, false);
        data.exclude = true;
        label.setLayoutData(data);
        label.setVisible(false);
    }

    /** Shows {@code text} (null: hides the banner); lays the window out only when that changes. */
    void show(String text) {
        boolean on = text != null;
        if (on && !text.equals(label.getText())) {
            label.setText(text);
        }
        if (on != label.getVisible()) {
            label.setVisible(on);
            data.exclude = !on;
            label.getParent().layout(true, false);
        }
    }

    /** The banner's text while it is shown, else null. */
    String shown() {
        return label.getVisible() ? label.getText() : null;
    }
}
