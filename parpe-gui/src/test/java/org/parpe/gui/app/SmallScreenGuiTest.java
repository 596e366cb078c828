package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.Arrays;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.ToolBar;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Issue 23, item 4: at 1366×768, the common classroom laptop, Hardware… and the profile fell off
 * the run tool bar, the 3D bar lost Module IDs and Reset view, the grid buttons wrapped and the
 * joint list showed "module" without numbers. Now what does not fit goes behind a chevron (»)
 * whose menu still reaches it, nothing is drawn past a bar's edge, and the window remembers being
 * maximised. Real widgets under Xvfb, in a window of exactly 1366×768.
 */
class SmallScreenGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    private static List<String> texts(Menu m) {
        return Arrays.stream(m.getItems()).map(MenuItem::getText).toList();
    }

    /** Every visible child of {@code bar} lies inside it. */
    private static void inside(Composite bar) {
        Rectangle area = bar.getClientArea();
        for (Control c : bar.getChildren()) {
            Rectangle b = c.getBounds();
            assertTrue(!c.getVisible() || b.x >= 0 && b.x + b.width <= area.width,
                    c + " is drawn past the edge of its bar: " + b + " in " + area);
        }
    }

    @Test
    void atLaptopSizeNothingFallsOffTheBarsAndTheChevronReachesIt() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-1366"));
        ide.shell.setBounds(0, 0, 1366, 768);
        Gui.open(ide, Gui.example("tutorial/02-gait-table-snake.xml"));
        Gui.pump(() -> ide.program() != null, "the lesson to load");
        assertTrue(ide.grid.showTable("travel"));
        Gui.settle();

        var run = (Composite) ide.toolbar.control();
        var overflow = (org.parpe.gui.panels.OverflowBar) run.getData(org.parpe.gui.panels.OverflowBar.KEY);
        inside(run);
        assertTrue(overflow.overflowing(), "at 1366 pixels the run tool bar does not hold everything");
        assertTrue(Arrays.stream(run.getChildren()).anyMatch(c -> c instanceof ToolBar && c.getVisible()),
                "Run, Stop and the emergency stop stay in sight");
        Menu more = overflow.menu();
        assertTrue(texts(more).contains("Hardware\u2026"), "Hardware… is in the chevron's menu: " + texts(more));
        more.dispose();

        var view = (Composite) ide.viewBar.control();
        var viewOverflow = (org.parpe.gui.panels.OverflowBar) view.getData(org.parpe.gui.panels.OverflowBar.KEY);
        inside(view);
        if (viewOverflow.overflowing()) {
            Menu m = viewOverflow.menu();
            MenuItem ids = Arrays.stream(m.getItems()).filter(i -> i.getText().equals("Module IDs")).findFirst().orElseThrow(
                    () -> new AssertionError("Module IDs is neither in the 3D bar nor behind its chevron: " + texts(m)));
            ids.setSelection(true);
            ids.notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
            assertTrue(ide.view.showIds(), "the menu's Module IDs turns the labels on");
            m.dispose();
        }

        Composite gridBar = ide.grid.toolBar();
        inside(gridBar);
        int rowHeight = Arrays.stream(gridBar.getChildren()).filter(c -> c instanceof Button).mapToInt(c -> c.getSize().y)
                .max().orElse(0);
        assertTrue(gridBar.getSize().y < 2 * rowHeight, "the grid's buttons are one row, not wrapped: " + gridBar.getSize());

        org.eclipse.swt.widgets.List modules = Arrays.stream(((Composite) ide.plots.control()).getChildren())
                .filter(c -> c instanceof org.eclipse.swt.widgets.List).map(c -> (org.eclipse.swt.widgets.List) c)
                .findFirst().orElseThrow();
        assertEquals("m0", modules.getItem(0), "the joint list names modules as the chart's legend does");
        assertTrue(modules.getSize().x >= modules.computeSize(SWT.DEFAULT, SWT.DEFAULT).x - 20,
                "the joint list is wide enough for its names");
        Gui.screenshot(ide.shell, "ide-1366x768.png");
    }

    @Test
    void theWindowRemembersBeingMaximised() throws Exception {
        var home = Files.createTempDirectory("parpe-max");
        ide = Gui.openIde(home);
        ide.shell.setMaximized(true);
        Gui.settle();
        assertTrue(ide.closeRequested());
        ide.shell.close();
        assertEquals("true", new Prefs(home).get("window.maximised", "false"));
        ide = Gui.openIde(home);
        assertTrue(ide.shell.getMaximized(), "the window opens maximised again");
        assertFalse(ide.shell.isDisposed());
    }

    @Test
    void panesKeepTheirMinimumWhenSqueezed() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-panes"));
        ide.shell.setBounds(0, 0, 1366, 768);
        Gui.settle();
        ide.mainSash.setWeights(1, 98, 1);
        Gui.pump(() -> ide.mainSash.getChildren()[0].getSize().x >= 115, "the outline to grow back to its minimum");
        Gui.settle();
        Control[] panes = Arrays.stream(ide.mainSash.getChildren()).filter(c -> !(c instanceof org.eclipse.swt.widgets.Sash))
                .toArray(Control[]::new);
        assertTrue(panes[0].getSize().x >= 115, "outline " + panes[0].getSize());
        assertTrue(panes[2].getSize().x >= 295, "3D view " + panes[2].getSize());
        assertTrue(panes[1].getSize().x >= 415, "editor " + panes[1].getSize());
    }

    /**
     * Issue 31, item 3: at 1366×768 a long status message was cut off mid-word at the bar's edge.
     * Now the field shows what fits, cut after a word with "…", and its tooltip the whole text.
     */
    @Test
    void aLongStatusMessageIsShortenedWithTheWholeTextInItsTooltip() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-1366-status"));
        ide.shell.setBounds(0, 0, 1366, 768);
        Gui.settle();
        String text = "Score 166.0 (zone 39.0 s, path 12.30 m, 1 delivered, 2 presses) \u2014 run completed at t = 60.00 s;"
                + " the robot travelled 12.345 m (0.206 m/s, forward +12.300 m); it fell over (see Problems)";
        ide.status.setMessage(text);
        Gui.settle();
        org.eclipse.swt.widgets.Label field = ide.status.messageField();
        String shown = field.getText();
        org.eclipse.swt.graphics.GC gc = new org.eclipse.swt.graphics.GC(field);
        int width;
        try {
            width = gc.textExtent(shown).x;
        } finally {
            gc.dispose();
        }
        assertTrue(width <= field.getSize().x, "the message fits its field: " + width + " > " + field.getSize().x + ": " + shown);
        assertTrue(shown.endsWith("\u2026") && text.startsWith(shown.substring(0, shown.length() - 1)),
                "the message is its start and an ellipsis: " + shown);
        assertTrue(shown.startsWith("Score 166.0 (zone 39.0 s, path 12.30 m"), "what matters first stays: " + shown);
        assertFalse(Character.isLetterOrDigit(text.charAt(shown.length() - 1)) && Character.isLetterOrDigit(shown.charAt(shown.length() - 2)),
                "cut after a word, not inside one: " + shown);
        assertEquals(text, field.getToolTipText(), "the tooltip has the whole message");
        assertEquals(text, ide.status.message());
        ide.shell.setBounds(0, 0, 1920, 1000);
        Gui.settle();
        assertTrue(field.getText().length() > shown.length(), "a wider window shows more of it: " + field.getText());
    }
}
