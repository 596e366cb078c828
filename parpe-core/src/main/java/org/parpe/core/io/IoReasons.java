package org.parpe.core.io;

import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import org.parpe.core.text.Msg;

/**
 * The reason of a failed file operation in words, for every message that names a file and
 * then says why: java.nio's {@link FileSystemException}s carry the file as their message and
 * the reason apart (or none: {@link NoSuchFileException}, {@link AccessDeniedException}), so
 * "cannot read X: " + message said "cannot read X: X".
 */
public final class IoReasons {
    private IoReasons() {
    }

    /** Why {@code e} happened, without the file name the caller already gives. */
    public static String of(Throwable e) {
        if (e instanceof NoSuchFileException) {
            return Msg.NO_SUCH_FILE.text();
        }
        if (e instanceof AccessDeniedException) {
            return Msg.PERMISSION_DENIED.text();
        }
        if (e instanceof NotDirectoryException) {
            return Msg.FOLDER_IS_FILE.text();
        }
        if (e instanceof FileSystemException fs) {
            return fs.getReason() != null ? fs.getReason() : fs.getClass().getSimpleName();
        }
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }
}
