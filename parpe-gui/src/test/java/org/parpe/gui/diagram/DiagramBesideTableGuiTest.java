package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;

/**
 * Issue 31, item 2: at 1366×768 with a gait table open beside the text, the Diagram tab shrank
 * to 380 pixels, the palette's Add buttons were hidden under the message line, the drawing had
 * no height and a help sentence wrapped one syllable per line; an edit moved the drawing under
 * the mouse. Real widgets under Xvfb in a window of exactly 1366×768 on a copy of
 * {@code examples/gait-table-12.xml}, whose table the grid shows.
 */
class DiagramBesideTableGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        if (ide != null) {
            IdeAccess.closeIde(ide);
        }
    }

    /** The IDE at 1366×768, the Diagram tab shown first (or last: {@code tabFirst} false), the gait-table example open. */
    private DiagramPane open(boolean tabFirst) throws Exception {
        Path home = Files.createTempDirectory("parpe-diagram-table");
        Path copy = Files.createDirectories(home.resolve("scripts")).resolve("gait-table-12.xml");
        Files.copy(Path.of(System.getProperty("parpe.examples", "../examples"), "gait-table-12.xml"), copy);
        ide = IdeAccess.openIde(home);
        IdeAccess.shell(ide).setBounds(0, 0, 1366, 768);
        IdeAccess.dontSave(ide);
        DiagramPane pane = IdeAccess.diagram(ide);
        if (tabFirst) {
            assertEquals("Diagram", pane.showTab());
        }
        IdeAccess.open(ide, copy);
        if (!tabFirst) {
            assertEquals("Diagram", pane.showTab());
        }
        IdeAccess.pump(() -> pane.current() && IdeAccess.program(ide) != null && IdeAccess.grid(ide).visible(),
                "the diagram, the loaded script and its gait table in the grid");
        IdeAccess.settle();
        return pane;
    }

    /** The Diagram tab keeps at least its share (the larger part of the window), and the drawing half of the tab. */
    private void keepsItsShare(DiagramPane pane) {
        int window = IdeAccess.shell(ide).getClientArea().width;
        int tab = pane.control().getSize().x;
        assertTrue(2 * tab >= window, "the Diagram tab is " + tab + " px wide of the window's " + window);
        DiagramWindow.canvasHasHalfTheTab(ide);
    }

    @Test
    void openingAGaitTableWithTheDiagramShownKeepsTheDiagramsShare() throws Exception {
        keepsItsShare(open(true));
    }

    @Test
    void showingTheDiagramBesideAGaitTableGivesItItsShare() throws Exception {
        keepsItsShare(open(false));
    }

    /** Every palette item's Add button lies inside the pane, above the message line, wholly visible. */
    @Test
    void everyAddButtonIsInSightAndNoHelpLineIsNarrowerThanAWord() throws Exception {
        DiagramPane pane = open(true);
        pane.palette().full(true);
        for (String item : pane.palette().items()) {
            pane.palette().choose(item);
            IdeAccess.settle();
            Button add = pane.actions().get("Add " + item.toLowerCase(java.util.Locale.ROOT));
            assertNotNull(add, item + ": no Add button; buttons: " + pane.actions().keySet());
            Rectangle b = onScreen(add);
            Rectangle area = onScreen(pane.control());
            assertTrue(add.isVisible() && area.contains(b.x, b.y) && area.contains(b.x + b.width - 1, b.y + b.height - 1),
                    item + ": its Add button " + b + " is not inside the pane " + area);
            Rectangle row = onScreen(add.getParent());
            assertTrue(row.contains(b.x + b.width - 1, b.y + b.height - 1),
                    item + ": its Add button " + b + " is cut off by the edit row " + row);
            Rectangle canvas = onScreen(pane.canvas());
            assertTrue(b.y + b.height <= canvas.y, item + ": its Add button " + b + " is under the drawing " + canvas);
            for (Control c : all((Composite) pane.control())) {
                if (c instanceof Label l && c.isVisible() && (l.getStyle() & SWT.WRAP) != 0 && !l.getText().isBlank()
                        && c.getParent().isVisible()) {
                    assertTrue(onScreen(l).y >= b.y + b.height || onScreen(l).y + onScreen(l).height <= b.y,
                            item + ": the line '" + l.getText() + "' overlaps its Add button");
                    int word = widestWord(l);
                    assertTrue(l.getSize().x >= word, "'" + l.getText() + "' is " + l.getSize().x
                            + " px wide, narrower than its longest word (" + word + " px)");
                }
            }
        }
    }

    /**
     * A time typed into the selected entry, a refused value and an Add that fails: the drawing
     * and the sashes stay where they were (the mouse is still over them).
     */
    @Test
    void afterAnEditTheDrawingAndTheSashesStayWhereTheyWere() throws Exception {
        DiagramPane pane = open(true);
        DiagramDriver d = new DiagramDriver(ide);
        d.click(d.node("<slither/>"));
        IdeAccess.settle();
        Rectangle canvas = onScreen(pane.canvas());
        Rectangle tab = onScreen(pane.control());
        d.type("time", "8");
        IdeAccess.settle();
        assertTrue(d.text().contains("<slither time=\"8\"/>"), d.text());
        assertEquals(canvas, onScreen(pane.canvas()), "the drawing after a time was written");
        assertEquals(tab, onScreen(pane.control()), "the Diagram tab after a time was written");
        d.click(d.node("<slither"));
        d.type("time", "-1");
        IdeAccess.settle();
        assertTrue(!pane.message().isEmpty(), "a refused value is said");
        assertEquals(canvas, onScreen(pane.canvas()), "the drawing after a refused value");
        assertEquals(tab, onScreen(pane.control()), "the Diagram tab after a refused value");
        pane.palette().choose("Pose");
        IdeAccess.settle();
        canvas = onScreen(pane.canvas());
        d.press("Add pose", "name", "", "angles", "");
        IdeAccess.settle();
        assertEquals(canvas, onScreen(pane.canvas()), "the drawing after an Add refused with a message: " + pane.message());
        assertEquals(tab, onScreen(pane.control()), "the Diagram tab after an Add refused");
    }

    /** A gait table added from the palette opens the grid beside the text: the Diagram tab does not move for it. */
    @Test
    void aGaitTableAddedFromThePaletteDoesNotMoveTheDiagram() throws Exception {
        DiagramWindow.Opened o = DiagramWindow.open(Files.createTempDirectory("parpe-diagram-add-table"));
        ide = o.ide();
        IdeAccess.dontSave(ide);
        DiagramPane pane = IdeAccess.diagram(ide);
        DiagramDriver d = new DiagramDriver(ide);
        assertTrue(!IdeAccess.grid(ide).visible(), "the centipede walk has no gait table");
        pane.palette().choose("Gait table");
        IdeAccess.settle();
        Rectangle canvas = onScreen(pane.canvas());
        Rectangle tab = onScreen(pane.control());
        addTable(d, "wave", 2);
        IdeAccess.pump(() -> IdeAccess.grid(ide).visible(), "the grid to show the new table");
        IdeAccess.settle();
        assertEquals(tab, onScreen(pane.control()), "the Diagram tab after the grid opened");
        assertEquals(canvas, onScreen(pane.canvas()), "the drawing after the grid opened");
    }

    /** Adds gait table {@code name} of {@code rows} rows with the palette's inputs (already chosen). */
    static void addTable(DiagramDriver d, String name, int rows) {
        d.press("Add gait table", "name", name, "rows", Integer.toString(rows), "modules", "2");
    }

    private static Rectangle onScreen(Control c) {
        Rectangle b = c.getBounds();
        org.eclipse.swt.graphics.Point p = c.getParent().toDisplay(b.x, b.y);
        return new Rectangle(p.x, p.y, b.width, b.height);
    }

    private static int widestWord(Label l) {
        GC gc = new GC(l);
        try {
            int w = 0;
            for (String word : l.getText().split("\\s+")) {
                w = Math.max(w, gc.textExtent(word).x);
            }
            return w;
        } finally {
            gc.dispose();
        }
    }

    private static List<Control> all(Composite c) {
        List<Control> out = new ArrayList<>();
        for (Control k : c.getChildren()) {
            out.add(k);
            if (k instanceof Composite kc) {
                out.addAll(all(kc));
            }
        }
        return out;
    }
}
