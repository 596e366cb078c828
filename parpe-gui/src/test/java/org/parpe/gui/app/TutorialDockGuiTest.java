package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.Arrays;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.RGB;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.gui.help.TutorialWindow;
import org.parpe.gui.panels.Theme;

/**
 * Issue 31, item 3: at 1366×768 the tutorial's window covered the 3D view and the Diagram, its
 * table of lessons wrapped cell into cell, and its pictures, screenshots scaled to the column,
 * could not be read. Now Help > Tutorial docks it as a tab beside Outline (the 3D view stays in
 * sight), a table too wide for the column reads as one card per row, and a click on a picture
 * shows it at full size. With a dark theme (scripts/ide-screenshots' GTK_THEME=Adwaita:dark) the
 * docked tutorial is dark too. Real widgets in a window of 1366×768.
 */
class TutorialDockGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Arrays.stream(Gui.display().getShells()).filter(s -> !s.isDisposed() && s.getText().endsWith(".png")).forEach(Shell::dispose);
        Gui.closeIde(ide);
    }

    private static Rectangle onScreen(Control c) {
        return c.getDisplay().map(c.getParent(), null, c.getBounds());
    }

    private static double luminance(RGB c) {
        return (0.2126 * c.red + 0.7152 * c.green + 0.0722 * c.blue) / 255;
    }

    @Test
    void atLaptopSizeTheTutorialIsDockedBesideTheEditorAndThe3DView() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-tutorial-dock"));
        ide.shell.setBounds(0, 0, 1366, 768);
        Gui.settle();
        MenuItem help = Arrays.stream(ide.shell.getMenuBar().getItems()).filter(i -> i.getText().replace("&", "").equals("Help"))
                .findFirst().orElseThrow();
        MenuItem tutorialItem = Arrays.stream(help.getMenu().getItems()).filter(i -> i.getText().replace("&", "").equals("Tutorial"))
                .findFirst().orElseThrow();
        tutorialItem.notifyListeners(SWT.Selection, new Event());
        Gui.settle();
        assertEquals(0, Arrays.stream(Gui.display().getShells()).filter(s -> !s.isDisposed() && "PARPE tutorial".equals(s.getText()))
                .count(), "no tutorial window over the IDE");
        TutorialWindow t = ide.tutorialDock.tutorial();
        assertNotNull(t, "the tutorial is docked in the IDE");
        assertTrue(t.isDocked() && t.control().isVisible(), "the docked tutorial is in front");
        Rectangle lesson = onScreen(t.control());
        Rectangle view = onScreen(ide.view.control());
        Rectangle editor = onScreen(ide.editor.widget());
        assertTrue(!lesson.intersects(view) && !lesson.intersects(editor), "the tutorial " + lesson + " covers neither the 3D view "
                + view + " nor the editor " + editor);
        assertTrue(view.width >= 300 && editor.width >= 300 && lesson.width >= 400, "all three are usable: tutorial " + lesson
                + ", editor " + editor + ", 3D view " + view);

        // the Diagram in front of the 3D view's column: the tutorial keeps its column
        org.eclipse.swt.custom.CTabFolder views = (org.eclipse.swt.custom.CTabFolder) ide.view.control().getParent().getParent();
        views.setSelection(Arrays.stream(views.getItems()).filter(i -> i.getText().equals("Diagram")).findFirst().orElseThrow());
        views.notifyListeners(SWT.Selection, new Event());
        Gui.settle();
        Rectangle withDiagram = onScreen(t.control());
        assertTrue(withDiagram.width >= 400 && !withDiagram.intersects(onScreen(ide.diagram.control())),
                "beside the Diagram the tutorial " + withDiagram + " keeps its column");

        // the table of lessons on the first page: cards, not cells wrapped into each other's columns
        StyledText text = t.textWidget();
        assertTrue(t.shownText().contains("you will learn: what a module is"), "the table reads as cards:\n" + t.shownText());
        for (int l = 0; l < text.getLineCount(); l++) {
            String line = text.getLine(l);
            if (line.contains("\t")) {
                int at = text.getOffsetAtLine(l);
                assertEquals(text.getLocationAtOffset(at).y, text.getLocationAtOffset(at + line.length()).y,
                        "a table row wraps: " + line);
            }
        }
        Gui.screenshot(ide.shell, "tutorial-docked-1366x768-" + IdeScreenshotsTest.theme() + ".png");

        // a lesson's picture, scaled to the column, opens at full size
        t.show(3);
        Gui.settle();
        int picture = t.shownText().indexOf('\uFFFC');
        assertTrue(picture >= 0, "lesson 3 has its picture");
        assertTrue(t.clickable().stream().anyMatch(r -> r[0] <= picture && picture < r[0] + r[1]), "the picture is clickable");
        t.clickAt(picture);
        Gui.settle();
        Shell full = Arrays.stream(Gui.display().getShells()).filter(s -> !s.isDisposed() && s.getText().endsWith(".png"))
                .findFirst().orElseThrow(() -> new AssertionError("no picture window"));
        Label img = (Label) ((org.eclipse.swt.widgets.Composite) full.getChildren()[0]).getChildren()[0];
        ImageData file = new ImageData(Examples0.tutorialImage(full.getText()));
        assertEquals(file.width, img.getImage().getBounds().width, "the picture at its full width");
        full.dispose();

        if (Theme.dark()) {
            assertTrue(luminance(text.getBackground().getRGB()) < 0.4, "the lesson is dark in a dark theme: " + text.getBackground());
            assertTrue(luminance(text.getForeground().getRGB()) > 0.6, "its text is light: " + text.getForeground());
        }
    }

    /** Where the tutorial's pictures are. */
    private static final class Examples0 {
        static String tutorialImage(String name) {
            return org.parpe.gui.files.Examples.tutorialFolder().resolve("img").resolve(name).toString();
        }
    }
}
