package org.parpe.gui.app;

import java.nio.file.Path;
import java.util.List;
import org.eclipse.swt.widgets.Shell;

/**
 * What the window's bridges to the features' host interfaces share: the window, and the parts of
 * it that more than one feature asks for. A bridge implements its feature's host interface with
 * these where the interface asks the same. UI thread only.
 */
abstract class WindowBridge {
    final IdeWindow ide;

    WindowBridge(IdeWindow ide) {
        this.ide = ide;
    }

    /** The window's shell, the parent of a feature's dialogs. */
    public Shell shell() {
        return ide.shell;
    }

    /** The files open in the editor's tabs. */
    public List<Path> openFiles() {
        return ide.files.openFiles();
    }

    /** The robot chosen in the view bar for the current file. */
    public String robotChoice() {
        return ide.robotChoice();
    }
}
