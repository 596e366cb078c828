package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.widgets.Display;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.parpe.gui.diagram.DiagramPane;
import org.parpe.gui.editor.ScriptDocument;

/**
 * Issue 32, item 2: the IDE reads the open script once per version of its text, however many
 * views show it. With the Diagram tab (and its palette), Problems, the outline and the Pose panel
 * all open, each edit costs exactly one load (it cost two: the diagram loaded the text again
 * beside the live validation). The count is the document's own (how many texts the loader read),
 * not a time.
 */
class OneLoadPerEditGuiTest {
    private IdeWindow ide;

    @BeforeEach
    void openWindow() throws Exception {
        Path home = Files.createTempDirectory("parpe-one-load");
        Path copy = Files.createDirectories(home.resolve("scripts")).resolve("hello-snake.xml");
        Files.copy(Gui.example("hello-snake.xml"), copy);
        ide = Gui.openIde(home, 1366, 768);
        Gui.open(ide, copy);
        ide.bottom.showPose();
        DiagramPane pane = ide.diagram;
        pane.showTab();
        Gui.pump(() -> pane.current() && ide.program() != null, "the first diagram and the loaded script");
    }

    @AfterEach
    void closeWindow() {
        Gui.closeIde(ide);
    }

    @Test
    void eachEditIsLoadedOnceWithEveryViewOpen() {
        DiagramPane pane = ide.diagram;
        for (int edit = 1; edit <= 3; edit++) {
            // what the views show of the text before the edit is done, and the window is quiet
            Gui.pump(() -> pane.current() && !ide.document.busy(), "the views to show the text");
            Gui.settle();
            int loadsBefore = ide.document.loads();
            int validationsBefore = ide.validations();
            var doc = ide.editor.document();
            ide.editor.widget().replaceTextRange(doc.get().indexOf("<main>"), 0, "<!-- edit " + edit + " -->\n  ");
            Gui.pump(() -> pane.current() && ide.validations() > validationsBefore && !ide.document.busy(),
                    "the diagram and Problems to show edit " + edit);
            Gui.settle();
            assertEquals(loadsBefore + 1, ide.document.loads(), "loads of the text after edit " + edit);
        }
    }

    @Test
    void aListenerSeesTheResultOfTheNewTextOnTheUiThread() {
        List<ScriptDocument.Loaded> seen = new ArrayList<>();
        List<Boolean> onUiThread = new ArrayList<>();
        ide.document.addListener(l -> {
            seen.add(l);
            onUiThread.add(Display.getCurrent() != null);
        });
        String broken = ide.editor.document().get().replace("<simpleWave />", "<simpleWaves />");
        ide.editor.document().set(broken);
        Gui.pump(() -> seen.stream().anyMatch(l -> l.text().equals(broken)), "the listener to hear of the new text");
        ScriptDocument.Loaded last = seen.get(seen.size() - 1);
        assertEquals(broken, last.text(), "the last result a listener heard of is the text's now");
        assertNull(last.program(), "the new text does not load");
        assertTrue(last.result().errors().stream().anyMatch(d -> d.message().contains("simpleWaves")),
                "its error names the unknown behavior: " + last.result().errors());
        assertEquals(last, ide.document.current(), "the document keeps it as the version now");
        assertFalse(onUiThread.contains(false), "listeners are told on the UI thread");
    }
}
