package org.parpe.gui.app;

import org.parpe.gui.files.Examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.concurrent.atomic.AtomicReference;
import org.eclipse.swt.SWT;
import org.eclipse.swt.dnd.Clipboard;
import org.eclipse.swt.dnd.TextTransfer;
import org.eclipse.swt.dnd.Transfer;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.Text;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.eclipse.jface.text.ITextOperationTarget;
import org.parpe.gui.grid.GridPane;

/**
 * The gait-table grid on the paper's Fig. 4 table, driven through its widgets (mouse and key
 * events sent to the table, text typed into the cell editor): a cell edit changes the text and
 * only the table, a text edit changes the grid, a bad entry is tinted with the script's own
 * message, a travelling wave fills the table. Examples open as copies that Save never writes
 * back; Save keeps a file's permissions. Screenshots go to {@code target/gui-test-artefacts}.
 */
class GridGuiTest {
    private static IdeWindow ide;
    private static Path home;

    @BeforeAll
    static void openWindow() throws Exception {
        home = Files.createTempDirectory("parpe-grid-test");
        ide = Gui.openIde(home);
        ide.files.answerWith((title, message, buttons) -> 1);
    }

    @AfterAll
    static void closeWindow() {
        Gui.closeIde(ide);
    }

    /**
     * Every test starts from a fresh untitled copy of the example with its table in the grid
     * (unsaved edits of the test before are discarded), so that no test depends on another's
     * order or leftovers (issue 32, item 6).
     */
    @BeforeEach
    void openTheExampleCopy() {
        ide.files.openExample(Gui.example("gait-table-12.xml"));
        Gui.pump(() -> !ide.files.reading() && ide.files.example() != null && !ide.files.dirty()
                && grid().visible() && grid().widget().getColumnCount() == 15
                && "12".equals(grid().widget().getColumn(13).getText()) && "travel".equals(grid().table().name()),
                "the example copy and its grid, headed by module IDs once the script has loaded");
    }

    private static GridPane grid() {
        return ide.grid;
    }

    /** Sends a mouse press on the cell at {@code row}, table column {@code column} (0 is the step number). */
    private static void click(int row, int column, int stateMask) {
        Table t = grid().widget();
        Rectangle b = t.getItem(row).getBounds(column);
        for (int type : new int[] {SWT.MouseDown, SWT.MouseUp}) {
            Event e = new Event();
            e.button = 1;
            e.x = b.x + b.width / 2;
            e.y = b.y + b.height / 2;
            e.stateMask = stateMask;
            t.notifyListeners(type, e);
        }
    }

    private static void key(int keyCode, char character) {
        Event e = new Event();
        e.keyCode = keyCode;
        e.character = character;
        grid().widget().notifyListeners(SWT.KeyDown, e);
    }

    private static String line(int lineNumber) {
        String[] lines = ide.editor.document().get().split("\n", -1);
        return lines[lineNumber - 1];
    }

    /** The first line that holds {@code needle}, or (with {@code start}) begins with it after its indentation. */
    private static int lineOf(String needle) {
        return lineOf(needle, false);
    }

    private static int lineOf(String needle, boolean start) {
        String[] lines = ide.editor.document().get().split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            if (start ? lines[i].trim().startsWith(needle) : lines[i].contains(needle)) {
                return i + 1;
            }
        }
        return -1;
    }

    @Test
    void anExampleOpensAsACopyWithItsTableInTheGrid() throws Exception {
        Path example = Gui.example("gait-table-12.xml");
        String before = Files.readString(example);
        ide.files.openExample(example);
        Gui.pump(() -> !ide.files.reading() && ide.files.example() != null && grid().visible()
                && grid().widget().getColumnCount() == 15 && "12".equals(grid().widget().getColumn(13).getText()),
                "the example copy and its grid, headed by module IDs once the script has loaded");
        assertNull(ide.files.file(), "an example opens as an untitled copy");
        assertEquals("travel", grid().table().name());
        assertEquals(8, grid().widget().getItemCount());
        assertEquals(15, grid().widget().getColumnCount(), "step, times, 12 modules and the filler");
        assertEquals("12", grid().widget().getColumn(13).getText(), "headers are the module IDs");
        assertEquals("-15", grid().widget().getItem(1).getText(2));
        assertEquals(before, Files.readString(example));
    }

    @Test
    void editingACellChangesOnlyThatEntryInTheText() {
        int rowLine = lineOf("-15,  15,  15,  15,  15, -15", true);
        String[] lines = ide.editor.document().get().split("\n", -1);
        click(1, 2, 0);
        assertEquals(1, grid().selection().r0());
        assertEquals(1, grid().selection().c0(), "grid column 1 is module 1");
        var entry = grid().table().cell(1, 0);
        assertEquals(entry.start(), ide.editor.viewer().getSelectedRange().x, "the focused cell's entry is selected in the text");
        assertEquals(3, ide.editor.viewer().getSelectedRange().y);
        key('7', '7');
        Text cell = grid().cellEditor();
        assertNotNull(cell, "typing in a cell opens its editor");
        cell.setText("7.5");
        cell.notifyListeners(SWT.DefaultSelection, new Event());
        Gui.pump(() -> line(rowLine).trim().startsWith("7.5,"), "the text to change");
        assertEquals(lines[rowLine - 1].length(), line(rowLine).length(), "the entry keeps its room: columns stay aligned");
        String[] now = ide.editor.document().get().split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            if (i != rowLine - 1) {
                assertEquals(lines[i], now[i], "line " + (i + 1) + " should not change");
            }
        }
        assertNull(grid().cellEditor(), "Enter closes the cell editor");
        assertEquals(2, grid().selection().r0(), "Enter moves down");
        ide.editor.run(ITextOperationTarget.UNDO);
        Gui.pump(() -> "-15".equals(grid().widget().getItem(1).getText(2)), "Undo to bring the grid back");
    }

    @Test
    void editingTheTextChangesTheGrid() throws Exception {
        int rowLine = lineOf("-15, -15, -15, -15,  15,  15,  15,  15", true);
        int offset = ide.editor.document().getLineOffset(rowLine - 1) + line(rowLine).indexOf("-15, -15, -15, -15");
        ide.editor.document().replace(offset, 3, "-20");
        Gui.pump(() -> "-20".equals(grid().widget().getItem(4).getText(2)), "the grid to show -20");
        assertEquals("-20", grid().table().cell(4, 0).text());
    }

    @Test
    void aBadEntryIsTintedWithTheScriptsOwnMessage() throws Exception {
        click(2, 5, 0);
        key(SWT.F2, '\0');
        Text cell = grid().cellEditor();
        assertNotNull(cell, "F2 opens the cell editor");
        cell.setText("$nowhere");
        grid().setDiagnostics(ide.problems().shown());
        assertTrue(cell == grid().cellEditor() && "$nowhere".equals(cell.getText()),
                "a validation result arriving while a cell is typed into must not drop the typing");
        cell.notifyListeners(SWT.DefaultSelection, new Event());
        Gui.pump(() -> ide.problems().errorCount() > 0 && grid().widget().getItem(2).getBackground(5).equals(GridPane.INVALID),
                "the bad cell to be tinted");
        int line = lineOf("$nowhere");
        var d = ide.problems().shown().stream().filter(p -> p.pos().line() == line).findFirst().orElseThrow();
        Rectangle b = grid().widget().getItem(2).getBounds(5);
        Event move = new Event();
        move.x = b.x + 2;
        move.y = b.y + 2;
        grid().widget().notifyListeners(SWT.MouseMove, move);
        assertEquals(d.message(), grid().widget().getToolTipText(), "the cell shows the same message as the text");
        assertTrue(grid().status().contains("1 cell has a problem"), grid().status());
        Gui.screenshot(ide.shell, "grid-invalid-cell.png");
        ide.editor.run(ITextOperationTarget.UNDO);
        Gui.pump(() -> ide.problems().errorCount() == 0 && !line(line).contains("$nowhere"), "Undo to remove the bad entry");
    }

    @Test
    void theWaveDialogAndCtrlVFillTheSelection() throws Exception {
        click(0, 2, 0);
        click(7, 13, SWT.SHIFT);
        assertEquals(8, grid().selection().rows());
        assertEquals(12, grid().selection().columns());
        AtomicReference<String> dialog = new AtomicReference<>();
        ide.shell.getDisplay().asyncExec(() -> answerWaveDialog("20", "0.125", dialog));
        button("Wave\u2026").notifyListeners(SWT.Selection, new Event());
        assertEquals("Fill with a travelling wave", dialog.get(), "the Wave\u2026 button should open its dialog");
        Gui.pump(() -> "14.1".equals(grid().widget().getItem(0).getText(3)), "the wave in the grid");
        assertEquals("20", grid().widget().getItem(2).getText(2), "20 sin(2pi 2/8)");
        assertTrue(ide.editor.document().get().contains("<!--        module: 1    2    3"), "the comment above the table stays");

        click(6, 2, 0);
        Clipboard cb = new Clipboard(ide.shell.getDisplay());
        cb.setContents(new Object[] {"1\t2\n3\t4\n"}, new Transfer[] {TextTransfer.getInstance()});
        cb.dispose();
        grid().widget().setFocus();
        Event paste = new Event();
        paste.keyCode = 'v';
        paste.character = 0x16;
        paste.stateMask = SWT.MOD1;
        grid().widget().notifyListeners(SWT.KeyDown, paste);
        Gui.pump(() -> "4".equals(grid().widget().getItem(7).getText(3)), "the pasted cells");
        assertEquals("1", grid().table().cell(6, 0).text());
        assertEquals(0, grid().paste("1,5\t7"), "nothing falls outside");
        assertEquals("7", grid().table().cell(6, 1).text());
        assertEquals("1", grid().table().cell(6, 0).text(), "a decimal comma would split the entry: left out");
        assertTrue(grid().status().contains("1 entry was left out"), grid().status());
        grid().select(0, 1, 7, 12);
        Gui.screenshot(ide.shell, "grid-wave.png");
    }

    /** Fills in the wave dialog once it is up (it runs its own event loop) and presses OK. */
    private static void answerWaveDialog(String amplitude, String phase, AtomicReference<String> title) {
        for (Shell s : ide.shell.getDisplay().getShells()) {
            if (s != ide.shell && s.isVisible() && !s.isDisposed()) {
                title.set(s.getText());
                java.util.List<Text> fields = new java.util.ArrayList<>();
                java.util.List<Button> buttons = new java.util.ArrayList<>();
                collect(s, fields, buttons);
                fields.get(0).setText(amplitude);
                fields.get(1).setText(phase);
                buttons.stream().filter(b -> "OK".equals(b.getText().replace("&", ""))).findFirst().orElseThrow()
                        .notifyListeners(SWT.Selection, new Event());
                return;
            }
        }
        ide.shell.getDisplay().timerExec(50, () -> answerWaveDialog(amplitude, phase, title));
    }

    private static void collect(Composite c, java.util.List<Text> fields, java.util.List<Button> buttons) {
        for (Control child : c.getChildren()) {
            if (child instanceof Text t) {
                fields.add(t);
            } else if (child instanceof Button b) {
                buttons.add(b);
            }
            if (child instanceof Composite k) {
                collect(k, fields, buttons);
            }
        }
    }

    private static Button button(String label) {
        java.util.List<Text> fields = new java.util.ArrayList<>();
        java.util.List<Button> buttons = new java.util.ArrayList<>();
        collect(grid().widget().getParent(), fields, buttons);
        return buttons.stream().filter(b -> label.equals(b.getText())).findFirst()
                .orElseThrow(() -> new AssertionError("no button '" + label + "' in the grid"));
    }

    @Test
    void rowButtonsAddAndRemoveRowsAndUndoTakesThemBack() throws Exception {
        String before = ide.editor.document().get();
        click(2, 3, 0);
        button("+Row").notifyListeners(SWT.Selection, new Event());
        Gui.pump(() -> grid().widget().getItemCount() == 9, "a ninth row");
        assertEquals(grid().table().texts().get(2), grid().table().texts().get(3), "the new row is a copy of the selected one");
        String after = ide.editor.document().get();
        assertEquals(before.substring(0, before.indexOf("<travel>")), after.substring(0, after.indexOf("<travel>")),
                "the text before the table is unchanged");
        click(0, 0, 0);
        click(1, 0, SWT.SHIFT);
        assertEquals(new org.parpe.gui.grid.Fill.Selection(0, 1, 1, 12), grid().selection(),
                "clicking step numbers selects the rows' module cells");
        button("\u2212Rows").notifyListeners(SWT.Selection, new Event());
        Gui.pump(() -> grid().widget().getItemCount() == 7, "two rows fewer");
        ide.editor.run(ITextOperationTarget.UNDO);
        ide.editor.run(ITextOperationTarget.UNDO);
        assertEquals(before, ide.editor.document().get(), "two Undos should restore the text");
        Gui.pump(() -> grid().widget().getItemCount() == 8, "the grid to show the 8 rows again");

        click(3, 5, 0);
        button("\u2212Cols").notifyListeners(SWT.Selection, new Event());
        Gui.pump(() -> grid().table().width() == 11, "a module column fewer");
        assertEquals(14, grid().widget().getColumnCount() - 1, "the 12 modules of the group stay as columns");
        assertEquals("", grid().widget().getItem(0).getText(13), "module 12 has no entry now");
        Gui.pump(() -> grid().status().contains("has 11 angles but group 'snake' has 12 modules"),
                "the row-length error of the script under the grid; it says: " + grid().status());
        ide.editor.run(ITextOperationTarget.UNDO);
        assertEquals(before, ide.editor.document().get(), "Undo should restore the column");
    }

    @Test
    void theCaretInAnotherTableShowsThatTable() throws Exception {
        String doc = ide.editor.document().get();
        int end = doc.indexOf("</automata>");
        ide.editor.document().replace(end, 0, "  <second>1, 2; 3, 4</second>\n  ");
        Gui.pump(() -> grid().tableNames().equals(java.util.List.of("travel", "second")), "the grid to find the new table");
        assertEquals("travel", grid().table().name(), "the grid stays on its table");
        int at = ide.editor.document().get().indexOf("3, 4</second>");
        ide.editor.widget().setCaretOffset(at);
        Gui.pump(() -> "second".equals(grid().table().name()), "the grid to follow the caret into 'second'");
        assertEquals("3", grid().widget().getItem(1).getText(2));
        ide.editor.run(ITextOperationTarget.UNDO);
        Gui.pump(() -> "travel".equals(grid().table().name()) && !ide.editor.document().get().contains("<second>"),
                "Undo to remove 'second'");
    }

    @Test
    void savingTheCopyAsksWhereAndNeverWritesTheExample() throws Exception {
        Path example = Gui.example("gait-table-12.xml");
        String before = Files.readString(example);
        Path target = home.resolve("my-gait.xml");
        AtomicReference<String> proposed = new AtomicReference<>();
        ide.files.chooseSaveTargetWith((folder, name) -> {
            proposed.set(name);
            assertTrue(!folder.startsWith(example.getParent().getParent()), "Save should not start in the install folder: " + folder);
            return target;
        });
        assertTrue(ide.files.save());
        assertEquals("gait-table-12.xml", proposed.get());
        assertEquals(ide.editor.document().get(), Files.readString(target));
        assertEquals(before, Files.readString(example), "the example was written");
        assertEquals(target, ide.files.file());
    }

    @Test
    void savingKeepsTheFilesPermissions() throws Exception {
        Path script = home.resolve("shared.xml");
        Files.writeString(script, Files.readString(Gui.example("gait-table-12.xml")));
        Files.setPosixFilePermissions(script, PosixFilePermissions.fromString("rwxrw-r--"));
        Gui.open(ide, script);
        ide.editor.document().replace(0, 0, "<!-- edited -->\n");
        assertTrue(ide.files.save());
        assertTrue(Files.readString(script).startsWith("<!-- edited -->"));
        assertEquals("rwxrw-r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(script)));
    }
}
