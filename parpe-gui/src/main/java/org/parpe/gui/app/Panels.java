package org.parpe.gui.app;

import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;


/** Small helpers that give every pane the same framed, titled look. */
final class Panels {
    static final Color SELECTED = org.parpe.gui.panels.Theme.pick(0xDCE6F4, 0x2F4A6E);

    private Panels() {
    }

    /** A tab folder with a border and the selected tab tinted. */
    static CTabFolder folder(Composite parent) {
        CTabFolder f = new CTabFolder(parent, SWT.BORDER | SWT.FLAT);
        f.setSimple(false);
        f.setTabHeight(24);
        f.setSelectionBackground(SELECTED);
        f.setFont(JFaceResources.getDialogFont());
        return f;
    }

    /** Adds a tab holding {@code content} (created by the caller with the folder as parent). */
    static CTabItem tab(CTabFolder folder, String title, Control content) {
        CTabItem it = new CTabItem(folder, SWT.NONE);
        it.setText(title);
        it.setControl(content);
        if (folder.getSelectionIndex() < 0) {
            folder.setSelection(it);
        }
        return it;
    }
}
