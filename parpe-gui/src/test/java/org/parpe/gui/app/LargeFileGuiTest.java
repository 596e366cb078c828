package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import org.parpe.gui.automation.Bench;
import org.parpe.gui.files.FileActions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import org.eclipse.swt.widgets.Tree;
import org.eclipse.swt.widgets.TreeItem;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.gui.panels.OutlineView;

/**
 * A 5 MB script opens without blocking the window: the file is read in the background (an
 * event posted before the open is handled while it is read), the editor then holds the whole
 * text, plain, and the outline lists a bounded number of entries. No timing is asserted.
 */
class LargeFileGuiTest {
    @TempDir
    Path dir;
    private IdeWindow ide;

    @AfterEach
    void closeWindow() {
        if (ide != null && !ide.shell.isDisposed()) {
            ide.shell.dispose();
        }
    }

    @Test
    void opensAFiveMegabyteScriptWhileTheWindowKeepsWorking() throws Exception {
        String text = Bench.largeScript(5 << 20);
        Path big = dir.resolve("big.xml");
        Files.writeString(big, text);
        ide = new IdeWindow(Gui.display(), new Prefs(dir.resolve("home")));
        ide.open(null, true);
        Gui.pump(() -> ide.validations() > 0, "the first validation");

        AtomicReference<String> seen = new AtomicReference<>();
        ide.shell.getDisplay().asyncExec(() -> seen.set("reading=" + ide.files.reading()
                + " length=" + ide.editor.document().getLength()));
        ide.files.openPath(big);
        Gui.pump(() -> seen.get() != null, "an event posted before the open");
        assertEquals("reading=true length=" + FileActions.template().length(), seen.get(),
                "the UI thread was busy with the file: it should be read in the background");
        assertFalse(ide.editor.viewer().isEditable(), "the editor should be read-only while the file is read");

        Gui.pump(() -> !ide.files.reading() && big.toAbsolutePath().normalize().equals(ide.files.file()), "the file to open");
        assertEquals(text.length(), ide.editor.document().getLength());
        assertEquals(text, ide.editor.document().get());
        assertTrue(ide.editor.viewer().isEditable());
        assertTrue(ide.editor.plain(), "a 5 MB text should be shown without colouring");
        assertFalse(ide.files.dirty());

        int before = ide.validations();
        Gui.pump(() -> ide.validations() > before || ide.program() != null && ide.program().states().size() > 2,
                "the large script to be validated");
        Gui.pump(() -> ide.program() != null && ide.program().states().size() > 2, "the large script to load");
        assertEquals(0, ide.problems().errorCount(), "generated script has errors: " + ide.problems().shown());
        assertTrue(ide.editor.names(text).states().contains("s1000"),
                "completion should know the states of the large script (scanned in the background)");
        Tree tree = ide.outline.control();
        int shown = 0;
        for (TreeItem section : tree.getItems()) {
            assertTrue(section.getItemCount() <= OutlineView.SECTION_LIMIT + 1,
                    section.getText() + " lists " + section.getItemCount() + " entries");
            shown += section.getItemCount();
        }
        assertTrue(shown > 0);
        assertTrue(ide.status.message().contains("no colouring"), "status bar should say colouring is off: "
                + ide.status.message());
        Gui.screenshot(ide.shell, "large-file.png");

        ide.files.newFile();
        assertFalse(ide.editor.plain(), "a small text should be coloured again");
    }
}
