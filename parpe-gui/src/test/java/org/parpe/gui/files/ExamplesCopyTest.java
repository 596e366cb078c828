package org.parpe.gui.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The installed examples are read-only, so lesson 11's {@code parpe optimize}, which writes beside
 * its script, failed on them (issue 22 §3): the installed PARPE works on the user's own copy.
 */
class ExamplesCopyTest {
    @TempDir
    Path dir;

    Path installedExamples() throws Exception {
        Path bundled = dir.resolve("opt/parpe/lib/app/examples");
        Files.createDirectories(bundled.resolve("tutorial"));
        Files.writeString(bundled.resolve("hello-snake.xml"), "<parsl/>");
        Files.writeString(bundled.resolve("tutorial/10-race-snake.xml"), "<parsl>race</parsl>");
        for (Path p : new Path[] {bundled.resolve("hello-snake.xml"), bundled.resolve("tutorial/10-race-snake.xml")}) {
            Files.setPosixFilePermissions(p, PosixFilePermissions.fromString("r--r--r--"));
        }
        return bundled;
    }

    @Test
    void aSourceCheckoutIsNotAnInstall() throws Exception {
        assertFalse(Examples.installed(Path.of("..", "examples").toAbsolutePath().normalize()));
        assertTrue(Examples.installed(installedExamples()));
    }

    @Test
    void theFirstUseCopiesEverythingWritableIntoTheHomeFolder() throws Exception {
        Path home = Files.createDirectories(dir.resolve("home"));
        Path copy = Examples.copyForUser(installedExamples(), home);
        assertEquals(home.resolve("PARPE/examples"), copy);
        assertEquals("<parsl>race</parsl>", Files.readString(copy.resolve("tutorial/10-race-snake.xml")));
        assertTrue(Files.isWritable(copy.resolve("tutorial/10-race-snake.xml")));
        assertTrue(Files.isWritable(copy.resolve("tutorial")));
    }

    @Test
    void aStudentsChangesAreKeptAndNewExamplesAppear() throws Exception {
        Path home = Files.createDirectories(dir.resolve("home"));
        Path bundled = installedExamples();
        Path copy = Examples.copyForUser(bundled, home);
        Files.writeString(copy.resolve("hello-snake.xml"), "<parsl>mine</parsl>");
        Files.writeString(bundled.resolve("wheel.xml"), "<parsl>new</parsl>");
        Examples.copyForUser(bundled, home);
        assertEquals("<parsl>mine</parsl>", Files.readString(copy.resolve("hello-snake.xml")));
        assertEquals("<parsl>new</parsl>", Files.readString(copy.resolve("wheel.xml")));
    }

    @Test
    void anUnwritableHomeFallsBackToTheInstalledExamples() throws Exception {
        Path bundled = installedExamples();
        Path home = Files.writeString(dir.resolve("not-a-folder"), "x");
        assertEquals(bundled, Examples.copyForUser(bundled, home));
    }
}
