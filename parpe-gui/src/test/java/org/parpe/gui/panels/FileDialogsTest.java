package org.parpe.gui.panels;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 23, item 15: file dialogs started in different places (Save profile… and Save CSV… in the
 * process's folder) and the hardware profile's GTK save dialog had no title. Every dialog now goes
 * through {@link FileDialogs}, which needs a title and starts in one place.
 */
class FileDialogsTest {
    @TempDir
    Path dir;

    @Test
    void everyDialogStartsBesideTheStudentsScriptElseWhereTheLastOneEndedElseInDocuments() throws Exception {
        Path install = Files.createDirectories(dir.resolve("opt/parpe-ide/lib/app"));
        Path examples = Files.createDirectories(install.resolve("examples"));
        Path home = Files.createDirectories(dir.resolve("home/anna"));
        assertEquals(home, FileDialogs.start(null, install, home, null), "no Documents folder: the home folder");
        Path documents = Files.createDirectories(home.resolve("Documents"));
        assertEquals(documents, FileDialogs.start(null, install, home, null));
        assertEquals(documents, FileDialogs.start(examples.resolve("hello-snake.xml"), install, home, null),
                "never the examples' install folder");
        assertEquals(documents, FileDialogs.start(install.resolve("docs/tutorial/x.xml"), install, home, null));
        assertEquals(documents, FileDialogs.start(home.resolve("gone/none.xml"), install, home, null), "a folder that is gone");
        Path mine = Files.createDirectories(home.resolve("robots"));
        assertEquals(mine, FileDialogs.start(mine.resolve("walk.xml"), install, home, null));
        assertEquals(mine, FileDialogs.start(mine.resolve("walk.xml"), null, home, null));
        Path profiles = Files.createDirectories(home.resolve("profiles"));
        assertEquals(profiles, FileDialogs.start(null, install, home, profiles), "an untitled script: where the last dialog ended");
        assertEquals(profiles, FileDialogs.start(examples.resolve("hello-snake.xml"), install, home, profiles));
        assertEquals(mine, FileDialogs.start(mine.resolve("walk.xml"), install, home, profiles), "the script's own folder first");
    }

    /** No dialog of the IDE makes its own FileDialog (its own start folder, perhaps no title): they all ask {@link FileDialogs}. */
    @Test
    void noFileDialogIsMadeOutsideFileDialogs() throws IOException {
        Path main = Path.of("src/main/java");
        assertTrue(Files.isDirectory(main), "run from parpe-gui: " + main.toAbsolutePath());
        List<String> found = new ArrayList<>();
        try (Stream<Path> files = Files.walk(main)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
                if (!f.endsWith("FileDialogs.java") && Files.readString(f).contains("new FileDialog(")) {
                    found.add(main.relativize(f).toString());
                }
            }
        }
        assertEquals(List.of(), found, "file dialogs made without FileDialogs.ask (a title and the common start folder)");
    }

    @Test
    void aDialogWithoutATitleIsRefused() {
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> FileDialogs.ask(null, org.eclipse.swt.SWT.SAVE, " ", "*.xml", null, null));
    }
}
