package org.parpe.gui.files;

import org.parpe.gui.text.UiMsg;
import java.io.IOException;
import java.nio.file.Path;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.io.AtomicFiles;

/**
 * Writes a script by the output rules ({@link AtomicFiles}): whole or not at all, keeping the
 * file's permissions, through a symbolic link to its target, never over anything but a regular
 * file; a new file gets the system's default permissions (umask). Also the Save As dialog that
 * chooses the file.
 */
final class SafeSave {
    private SafeSave() {
    }

    /** Writes {@code text} (UTF-8) to {@code target}. */
    static void write(Path target, String text) throws IOException {
        AtomicFiles.write(target, text);
    }

    /** The Save As dialog, starting in {@code folder} with {@code name}; the chosen file, or {@code null}. */
    static Path ask(Shell shell, Path folder, String name) {
        return org.parpe.gui.panels.FileDialogs.ask(shell, SWT.SAVE, UiMsg.SAVE_SCRIPT_TITLE.text(), "*.xml", name, folder);
    }
}
