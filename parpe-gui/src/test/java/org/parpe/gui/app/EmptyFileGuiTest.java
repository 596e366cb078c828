package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.RunOn;

/**
 * Issue 31, item 3: an empty file (0 bytes, white space, or a declaration and a comment) showed
 * an error in Problems and kept the previous script's outline, while the Diagram invited "Start a
 * robot". An empty file is a beginning, not a mistake: no problem, no outline, no robot of
 * another script, and the status bar says how to begin; Run says why it cannot run.
 */
class EmptyFileGuiTest {
    @TempDir
    static Path home;
    static IdeWindow ide;

    @BeforeAll
    static void open() {
        ide = Gui.openIde(home, 1366, 768);
    }

    @AfterAll
    static void close() {
        Gui.closeIde(ide);
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "  \n\n", "<?xml version=\"1.0\"?>\n<!-- my first robot -->\n"})
    void anEmptyFileShowsNoErrorAndNoOutlineOfTheScriptBefore(String empty) throws Exception {
        Gui.open(ide, Gui.example("hello-snake.xml"));
        Gui.pump(() -> ide.program() != null && ide.outline.control().getItemCount() > 0, "hello-snake's outline");

        Path f = Files.createTempDirectory("parpe-empty").resolve("mine.xml");
        Files.writeString(f, empty);
        int before = ide.validations();
        Gui.open(ide, f);
        Gui.pump(() -> ide.validations() > before, "the empty file's check");
        Gui.settle();
        assertEquals(0, ide.problems().shown().size(), "Problems is empty: " + ide.problems().shown());
        assertEquals(0, ide.outline.control().getItemCount(), "no outline of the script before");
        assertNull(ide.program());
        String status = ide.status.message();
        assertTrue(status.startsWith("The file is empty"), "the status bar says how to begin: " + status);
        assertFalse(status.contains("error"), status);

        // typed away: the text of a script deleted in the editor is an empty file too
        Gui.open(ide, Gui.example("hello-snake.xml"));
        Gui.pump(() -> ide.program() != null && ide.outline.control().getItemCount() > 0, "hello-snake again");
        int typed = ide.validations();
        ide.editor.document().set(empty);
        Gui.pump(() -> ide.validations() > typed, "the check of the emptied text");
        Gui.settle();
        assertEquals(0, ide.problems().shown().size(), "Problems is empty: " + ide.problems().shown());
        assertEquals(0, ide.outline.control().getItemCount(), "the deleted script's outline is gone");
        assertNull(ide.program());

        AtomicReference<RunOutcome> end = new AtomicReference<>();
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.runs.run(false, 1, end::set);
        assertEquals(RunOutcome.Status.ERROR, end.get().status());
        assertTrue(ide.status.message().startsWith("Cannot run: the file is empty"), ide.status.message());
        assertEquals(0, ide.problems().shown().size(), "Run adds no error either: " + ide.problems().shown());
        IdeAccess.dontSave(ide);
    }
}
