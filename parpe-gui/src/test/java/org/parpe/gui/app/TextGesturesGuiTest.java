package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.graphics.Point;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.gui.files.Examples;
import org.parpe.gui.help.TutorialWindow;

/**
 * Issue 31, item 1: double-clicking a word in the editor closed the IDE at once
 * ({@code NoClassDefFoundError: com/ibm/icu/text/BreakIterator}: jface.text's default double-click
 * strategy links ICU, which the jars leave out, only on a double-click). The mouse gestures a
 * user makes in each text widget of the IDE (the editor, the Run log, the tutorial's text):
 * double-click selects a word, triple-click a line, a drag selects, a middle click pastes what is
 * selected (X11's primary selection) into the editor and leaves read-only text as it was. Real
 * mouse events (Display.post, through the X server and GTK, which makes the double and triple
 * clicks) on the class path the product ships: Maven's test class path has the same exclusions as
 * the shaded jar and the image's jars (parpe-gui/pom.xml, packaging/dist.sh).
 */
class TextGesturesGuiTest {
    private static IdeWindow ide;

    @BeforeAll
    static void openWindow() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-gestures"));
        Gui.open(ide, Gui.example("hello-snake.xml"));
        ide.shell.forceActive();
        Gui.settle();
    }

    @AfterAll
    static void closeWindow() {
        Gui.closeIde(ide);
    }

    @Test
    void doubleClickSelectsANumberInTheEditorAndTheWindowLives() {
        StyledText w = ide.editor.widget();
        int at = ide.editor.document().get().indexOf("angles=\"30\"") + "angles=\"".length();
        doubleClick(w, at + 1);
        Gui.pump(() -> "30".equals(w.getSelectionText()), "the double-click to select 30; selected: '" + w.getSelectionText() + "'");
        assertFalse(ide.shell.isDisposed(), "the window closed on a double-click");
        doubleClick(w, ide.editor.document().get().indexOf("simpleWave") + 3);
        Gui.pump(() -> "simpleWave".equals(w.getSelectionText()), "the double-click to select simpleWave");
    }

    @Test
    void tripleClickDragAndMiddleClickInTheEditor() {
        StyledText w = ide.editor.widget();
        String text = ide.editor.document().get();
        int line = w.getLineAtOffset(text.indexOf("<up angles"));
        click(w, w.getOffsetAtLine(line) + 6, 1, 3);
        Gui.pump(() -> w.getSelectionText().strip().equals("<up angles=\"30\" />"),
                "the triple-click to select the line; selected: '" + w.getSelectionText() + "'");

        int from = text.indexOf("phase=");
        drag(w, from, from + "phase".length());
        Gui.pump(() -> "phase".equals(w.getSelectionText()), "the drag to select 'phase'; selected: '" + w.getSelectionText() + "'");
        assertEquals(text, ide.editor.document().get(), "selecting changed the text");

        // "phase" is the primary selection now: a middle click at the start of the <down> line pastes it there.
        int down = text.indexOf("<down");
        click(w, down, 2, 1);
        Gui.pump(() -> ide.editor.document().get().startsWith("phase<down", down),
                "the middle click to paste 'phase' before <down>");
        ide.editor.run(org.eclipse.jface.text.ITextOperationTarget.UNDO);
        assertEquals(text, ide.editor.document().get());
    }

    @Test
    void theRunLogSelectsByMouseAndItsSelectionPastesIntoTheEditor() {
        ide.bottom.log("servo 7 answered");
        StyledText log = ide.runLog();
        CTabFolder tabs = (CTabFolder) log.getParent();
        for (CTabItem item : tabs.getItems()) {
            if (item.getControl() == log) {
                tabs.setSelection(item);
            }
        }
        Gui.settle();
        String before = log.getText();
        int at = before.lastIndexOf("answered");
        gestures(log, at, "answered", log.getLine(log.getLineAtOffset(at)).strip());
        assertEquals(before, log.getText(), "the read-only log changed");

        doubleClick(log, at + 2);
        Gui.pump(() -> "answered".equals(log.getSelectionText()), "the log's word to be selected");
        StyledText editor = ide.editor.widget();
        String text = ide.editor.document().get();
        int down = text.indexOf("<down");
        click(editor, down, 2, 1);
        Gui.pump(() -> ide.editor.document().get().startsWith("answered<down", down),
                "the middle click to paste the log's word into the editor");
        ide.editor.run(org.eclipse.jface.text.ITextOperationTarget.UNDO);
        assertEquals(text, ide.editor.document().get());
    }

    @Test
    void theTutorialTextSelectsByMouse() {
        TutorialWindow t = new TutorialWindow(ide.shell, Examples.tutorialFolder(), p -> { }, code -> { });
        t.open();
        try {
            t.show(3);
            t.shell().forceActive();
            Gui.settle();
            StyledText w = t.textWidget();
            String before = w.getText();
            int at = before.indexOf("\nThe script\n") + "\nThe ".length();
            assertTrue(at > 5, "lesson 3 has no heading 'The script': " + before);
            gestures(w, at, "script", "The script");
            assertEquals(before, w.getText(), "the tutorial's text changed");
            assertFalse(t.shell().isDisposed());
        } finally {
            t.shell().dispose();
        }
    }

    /** Double, triple click, drag and middle click on read-only {@code w} at {@code word} (offset {@code at}). */
    private static void gestures(StyledText w, int at, String word, String line) {
        doubleClick(w, at + 2);
        Gui.pump(() -> word.equals(w.getSelectionText()), "the double-click to select '" + word + "'; selected: '"
                + w.getSelectionText() + "'");
        click(w, at + 2, 1, 3);
        Gui.pump(() -> w.getSelectionText().strip().equals(line), "the triple-click to select the line '" + line
                + "'; selected: '" + w.getSelectionText() + "'");
        drag(w, at, at + 4);
        Gui.pump(() -> word.substring(0, 4).equals(w.getSelectionText()), "the drag to select '" + word.substring(0, 4)
                + "'; selected: '" + w.getSelectionText() + "'");
        click(w, at, 2, 1);
        Gui.settle();
    }

    private static void doubleClick(StyledText w, int offset) {
        click(w, offset, 1, 2);
    }

    /** {@code count} presses of mouse {@code button} on the character at {@code offset} of {@code w}. */
    private static void click(StyledText w, int offset, int button, int count) {
        Point p = pointAt(w, offset);
        Gui.xdotool("mousemove", "--sync", Integer.toString(p.x), Integer.toString(p.y),
                "click", "--repeat", Integer.toString(count), "--delay", "60", Integer.toString(button));
        Gui.settle();
    }

    /**
     * Presses button 1 at {@code from}, moves to {@code to} in steps, and lets go; the IDE handles
     * each step before the next, as it does a hand's (GTK gives a move the pointer's position when
     * it reads the move, so moves all queued at once would arrive as one, after the press).
     */
    private static void drag(StyledText w, int from, int to) {
        // A press inside a selection would start a drag and drop: none is left.
        w.setSelection(w.getCaretOffset());
        Point a = pointAt(w, from);
        Point b = pointAt(w, to);
        Gui.xdotool("mousemove", "--sync", Integer.toString(a.x), Integer.toString(a.y), "mousedown", "1");
        Gui.settle();
        for (int i = 1; i <= 4; i++) {
            Gui.xdotool("mousemove", "--sync", Integer.toString(a.x + (b.x - a.x) * i / 4), Integer.toString(b.y));
            Gui.settle();
        }
        Gui.xdotool("mouseup", "1");
        Gui.settle();
    }

    /**
     * The display point of the character at {@code offset} (a little right of its left edge,
     * mid-line), scrolled into sight, after a pause so that the next press is not taken as one
     * more click of the gesture before.
     */
    private static Point pointAt(StyledText w, int offset) {
        long until = System.currentTimeMillis() + 600;
        Gui.pump(() -> System.currentTimeMillis() >= until, "a pause between gestures");
        w.setTopIndex(Math.max(0, w.getLineAtOffset(offset) - 3));
        Gui.settle();
        Point p = w.getLocationAtOffset(offset);
        Point on = w.toDisplay(p.x + 2, p.y + w.getLineHeight(offset) / 2);
        assertTrue(w.getDisplay().getBounds().contains(on) && w.getShell().getBounds().contains(on),
                "character " + offset + " of " + w + " is off the screen at " + on);
        return on;
    }

}
