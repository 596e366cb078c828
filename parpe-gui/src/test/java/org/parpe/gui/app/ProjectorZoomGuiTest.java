package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.Arrays;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Table;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Issue 31, item 2: at projector zoom the gait table showed "-3(" for "-30" (its columns kept
 * their width while the font grew), and the zoom was in no menu. Now View → Zoom In / Zoom Out /
 * Reset Zoom (accelerators shown) drive the one zoom of the window, and the grid's columns follow
 * it. Real widgets under Xvfb, in a window of 1366×768.
 */
class ProjectorZoomGuiTest {
    /** What GTK's cell renderer takes of a column's width beside the text (its padding and focus line). */
    private static final int CELL_MARGIN = 6;
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    private MenuItem viewItem(String text) {
        Menu bar = ide.shell.getMenuBar();
        Menu view = Arrays.stream(bar.getItems()).filter(i -> i.getText().equals("&View")).findFirst().orElseThrow().getMenu();
        return Arrays.stream(view.getItems()).filter(i -> i.getText().replace("&", "").startsWith(text)).findFirst()
                .orElseThrow(() -> new AssertionError("View has no " + text + ": "
                        + Arrays.stream(view.getItems()).map(MenuItem::getText).toList()));
    }

    private void choose(String text) {
        viewItem(text).notifyListeners(SWT.Selection, new Event());
        Gui.settle();
    }

    private int editorPoints() {
        return ide.editor.widget().getFont().getFontData()[0].getHeight();
    }

    @Test
    void theViewMenuZoomsInOutAndBack() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-zoom-menu"));
        ide.shell.setBounds(0, 0, 1366, 768);
        Gui.open(ide, Gui.example("hello-snake.xml"));
        for (String name : List.of("Zoom In", "Zoom Out", "Reset Zoom")) {
            MenuItem it = viewItem(name);
            assertNotEquals(0, it.getAccelerator(), name + " has a key");
            assertTrue(it.getText().contains("\tCtrl+"), name + " shows its key: " + it.getText());
        }
        int normal = editorPoints();
        int gridNormal = ide.grid.widget().getFont().getFontData()[0].getHeight();
        choose("Zoom In");
        assertEquals(1, ide.zoom());
        assertEquals(normal + 2, editorPoints(), "Zoom In makes the editor's text larger");
        assertEquals(gridNormal + 2, ide.grid.widget().getFont().getFontData()[0].getHeight(), "and the grid's");
        choose("Zoom In");
        choose("Zoom Out");
        assertEquals(1, ide.zoom());
        assertEquals(normal + 2, editorPoints(), "Zoom Out makes it smaller again");
        choose("Reset Zoom");
        assertEquals(0, ide.zoom());
        assertEquals(normal, editorPoints(), "Reset Zoom gives the normal size");
    }

    @Test
    void atTwiceTheTextEveryCellOfTheGaitTableFitsItsColumn() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-zoom-grid"));
        ide.shell.setBounds(0, 0, 1366, 768);
        Gui.open(ide, Gui.example("tutorial/02-gait-table-snake.xml"));
        Gui.pump(() -> ide.program() != null && ide.grid.visible(), "the lesson and its grid");
        Table t = ide.grid.widget();
        int normal = t.getFont().getFontData()[0].getHeight();
        while (t.getFont().getFontData()[0].getHeight() < 2 * normal) {
            choose("Zoom In");
        }
        Gui.settle();
        assertFits(t);
        Gui.screenshot(ide.shell, "grid-zoom-200.png");
        // an edit at this zoom (the grid is shown again) keeps the columns wide
        ide.grid.edited(0, 1, "-130");
        Gui.pump(() -> "-130".equals(t.getItem(0).getText(2)), "the edit in the grid");
        assertFits(t);
    }

    /** Every cell's and header's text, measured in the table's font, fits its column with the cell's margins. */
    private static void assertFits(Table t) {
        GC gc = new GC(t);
        try {
            gc.setFont(t.getFont());
            for (int c = 0; c < t.getColumnCount() - 1; c++) {
                int width = t.getColumn(c).getWidth();
                String header = t.getColumn(c).getText();
                assertTrue(gc.textExtent(header).x + CELL_MARGIN <= width, "header '" + header + "' is cut: "
                        + gc.textExtent(header).x + " px of text in a column of " + width);
                for (int r = 0; r < t.getItemCount(); r++) {
                    String s = t.getItem(r).getText(c);
                    assertTrue(gc.textExtent(s).x + CELL_MARGIN <= width, "'" + s + "' (row " + r + ", column " + c
                            + ") is cut: " + gc.textExtent(s).x + " px of text in a column of " + width);
                }
            }
        } finally {
            gc.dispose();
        }
    }
}
