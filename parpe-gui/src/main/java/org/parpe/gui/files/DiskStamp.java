package org.parpe.gui.files;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** What tells that a file was written since: its modification time, size and identity. */
record DiskStamp(Object modified, long size, Object key) {
    /** The stamp of {@code p} now; a file gone or unreadable has one of its own. */
    static DiskStamp of(Path p) {
        try {
            java.nio.file.attribute.BasicFileAttributes a = Files.readAttributes(p,
                    java.nio.file.attribute.BasicFileAttributes.class);
            return new DiskStamp(a.lastModifiedTime(), a.size(), a.fileKey());
        } catch (IOException e) {
            return new DiskStamp(null, -1, null); // gone
        }
    }
}
