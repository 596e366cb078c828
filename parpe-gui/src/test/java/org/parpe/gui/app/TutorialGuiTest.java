package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.gui.help.TutorialWindow;

/** Help → Tutorial: the lessons in order, a lesson with its picture, and its script opened in the editor. */
class TutorialGuiTest {
    private static IdeWindow ide;

    @BeforeAll
    static void openWindow() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-tutorial-home"));
    }

    @AfterAll
    static void closeWindow() {
        Gui.closeIde(ide);
    }

    @Test
    void theLessonsAreInOrderAndALessonOpensItsScript() throws Exception {
        Path folder = Examples.tutorialFolder();
        assertNotNull(folder, "docs/tutorial not found beside " + Examples.folder());
        assertTrue(Examples.lessons().size() >= 10, "File > Examples > Tutorial lessons lists " + Examples.lessons());
        TutorialWindow w = new TutorialWindow(ide.shell(), folder, p -> ide.files().openConfirmed(p));
        w.open();
        try {
            String[] titles = w.titles();
            assertTrue(titles.length >= 12, String.join(" | ", titles));
            assertTrue(titles[1].startsWith("Lesson 1") && titles[10].startsWith("Lesson 10"), String.join(" | ", titles));
            w.show(3);
            Gui.settle();
            assertTrue(w.shownText().startsWith(titles[3]), w.shownText());
            assertTrue(w.shownText().contains("\uFFFC"), "lesson 3's picture is not shown");
            Path script = w.script();
            assertNotNull(script, "lesson 3 names no script");
            assertEquals("03-hello-snake.xml", script.getFileName().toString());
            Gui.screenshot(w.shell(), "tutorial-lesson-3.png");
            ide.files().openConfirmed(script);
            Gui.pump(() -> !ide.files().reading() && script.toAbsolutePath().normalize().equals(ide.files().file()),
                    "the lesson's script in the editor");
        } finally {
            w.shell().dispose();
        }
    }

    /**
     * Issue 23, item 2: the tutorial was transient for the IDE (pinned above it, covering the
     * editor and the 3D view) and ran past the bottom of the screen. Now it is a window of its own
     * that fits the screen's working area, at 1366×768 too, and closes with the IDE.
     */
    @Test
    void theTutorialIsANormalWindowThatFitsOnTheScreen() throws Exception {
        IdeWindow small = Gui.openIde(Files.createTempDirectory("parpe-tutorial-small"));
        try {
            small.shell().setBounds(0, 0, 1366, 768);
            TutorialWindow w = new TutorialWindow(small.shell(), Examples.tutorialFolder(), p -> { });
            w.open();
            Gui.settle();
            assertNull(w.shell().getParent(), "the tutorial is not pinned above the IDE");
            org.eclipse.swt.graphics.Rectangle area = small.shell().getMonitor().getClientArea();
            org.eclipse.swt.graphics.Rectangle b = w.shell().getBounds();
            assertTrue(area.contains(b.x, b.y) && b.x + b.width <= area.x + area.width && b.y + b.height <= area.y + area.height,
                    "the tutorial " + b + " runs past the screen " + area);
            assertTrue(b.width <= area.width / 2 + 1 || b.width <= 1100, "it leaves room for the editor: " + b);
            small.shell().dispose();
            assertTrue(w.shell().isDisposed(), "the tutorial closes with the IDE");
        } finally {
            Gui.closeIde(small);
        }
    }
}
