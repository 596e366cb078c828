package org.parpe.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 31 item 5: messages lost their reason ("Cannot read X (X)"), java.nio's exceptions
 * carrying the file as their message. The exceptions here are the JDK's own, from real calls
 * (access denied cannot be provoked as root, who may read anything: it is the JDK's type).
 */
class IoReasonsTest {
    @TempDir
    Path dir;

    @Test
    void theReasonNotTheFileName() {
        Path missing = dir.resolve("missing.xml");
        IOException none = assertThrows(IOException.class, () -> Files.readString(missing));
        assertEquals("no such file", IoReasons.of(none));
        IOException folder = assertThrows(IOException.class, () -> Files.readString(dir));
        assertEquals("Is a directory", IoReasons.of(folder));
        assertEquals("permission denied", IoReasons.of(new AccessDeniedException(missing.toString())));
        assertEquals("disk full", IoReasons.of(new IOException("disk full")));
    }
}
