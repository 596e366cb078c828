package org.parpe.gui.files;


import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Save As starts in the user's documents for new scripts and bundled examples, else beside the file. */
class SaveFolderTest {
    @TempDir
    Path dir;

    @Test
    void newScriptsAndExamplesAreSavedToTheDocumentsFolder() throws Exception {
        Path install = Files.createDirectories(dir.resolve("opt/parpe-ide/lib/app"));
        Path examples = Files.createDirectories(install.resolve("examples"));
        Path home = Files.createDirectories(dir.resolve("home/anna"));
        assertEquals(home, FileActions.saveFolder(null, examples, home), "no Documents folder: the home folder");
        Path documents = Files.createDirectories(home.resolve("Documents"));
        assertEquals(documents, FileActions.saveFolder(null, examples, home));
        assertEquals(documents, FileActions.saveFolder(examples.resolve("hello-snake.xml"), examples, home));
        assertEquals(documents, FileActions.saveFolder(install.resolve("docs/tutorial/x.xml"), examples, home));
        Path mine = Files.createDirectories(home.resolve("robots"));
        assertEquals(mine, FileActions.saveFolder(mine.resolve("walk.xml"), examples, home));
        assertEquals(mine, FileActions.saveFolder(mine.resolve("walk.xml"), null, home));
    }
}
