package org.parpe.gui.app;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;


/** Small helpers that give every pane the same framed, titled look. */
final class Panels {
    static final Color SELECTED = org.parpe.gui.panels.Theme.pick(0xDCE6F4, 0x2F4A6E);

    private Panels() {
    }

    /** PARPE's icon (the one the desktop menu shows), for the window's title bar and task bar. */
    static Image icon(Display display) {
        try (InputStream in = Panels.class.getResourceAsStream("/org/parpe/gui/parpe.png")) {
            if (in == null) {
                throw new IllegalStateException("parpe.png is missing from the build of parpe-gui");
            }
            return new Image(display, in);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
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
