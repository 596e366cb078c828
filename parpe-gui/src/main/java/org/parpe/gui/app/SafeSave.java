package org.parpe.gui.app;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.util.Set;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.FileDialog;
import org.eclipse.swt.widgets.Shell;

/**
 * Writes a script so that a failure never leaves it half written and the file stays what it
 * was: an existing file is replaced atomically by a copy written beside it, which first gets
 * the file's POSIX permissions (the copy is created private, and an executable or group-writable
 * script must stay so); a new file is created with the system's default permissions (umask).
 * Also the Save As dialog that chooses the file.
 */
final class SafeSave {
    private SafeSave() {
    }

    /** Writes {@code text} (UTF-8) to {@code target}. */
    static void write(Path target, String text) throws IOException {
        if (!Files.exists(target)) {
            Files.writeString(target, text, StandardCharsets.UTF_8, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
            return;
        }
        Set<PosixFilePermission> perms = permissions(target);
        Path dir = target.toAbsolutePath().getParent();
        Path tmp = Files.createTempFile(dir, "." + target.getFileName(), ".tmp");
        try {
            Files.writeString(tmp, text, StandardCharsets.UTF_8);
            if (perms != null) {
                Files.setPosixFilePermissions(tmp, perms);
            }
            Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /** The Save As dialog, starting in {@code folder} with {@code name}; the chosen file, or {@code null}. */
    static Path ask(Shell shell, Path folder, String name) {
        FileDialog d = new FileDialog(shell, SWT.SAVE);
        d.setText("Save the script as");
        d.setFilterExtensions(new String[] {"*.xml", "*"});
        d.setOverwrite(true);
        d.setFileName(name);
        d.setFilterPath(folder.toString());
        String p = d.open();
        return p == null ? null : Path.of(p);
    }

    /** The file's POSIX permissions, or {@code null} where the file system has none (Windows). */
    private static Set<PosixFilePermission> permissions(Path p) throws IOException {
        try {
            return Files.getPosixFilePermissions(p);
        } catch (UnsupportedOperationException e) {
            return null;
        }
    }
}
