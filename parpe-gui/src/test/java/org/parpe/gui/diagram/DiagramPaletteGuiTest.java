package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Label;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.diagram.Scene;
import org.parpe.core.text.Lang;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.diagram.Projection.View;
import org.parpe.gui.text.PanelMsg;

/**
 * Issue 31, item 2: building by diagram needed the script's names typed into free-text fields
 * (they came only with Ctrl+Space, which nothing showed), the beginner palette had no Automaton,
 * a gait table was typed as {@code 0,0,…; 0,0,…}, nothing new was shown after Add, and labels
 * counted from zero ("entry 0", "#0"). Real widgets under Xvfb at 1366×768 on a copy of
 * {@code examples/centipede-walk.xml}; every edit is undone after its test.
 */
class DiagramPaletteGuiTest {
    private static IdeWindow ide;
    private static DiagramDriver d;
    private static String original;
    private static Path home;

    @BeforeAll
    static void openWindow() throws Exception {
        home = Files.createTempDirectory("parpe-diagram-palette");
        DiagramWindow.Opened o = DiagramWindow.open(home);
        ide = o.ide();
        IdeAccess.dontSave(ide);
        d = new DiagramDriver(ide);
        original = Files.readString(o.copy());
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    @AfterEach
    void backToTheExample() {
        while (!d.text().equals(original) && IdeAccess.editor(ide).viewer().getUndoManager().undoable()) {
            IdeAccess.editor(ide).run(org.eclipse.jface.text.ITextOperationTarget.UNDO);
        }
        assertEquals(original, d.text(), "the test's edits are undone");
        d.show(View.PROGRAM, null);
    }

    private static List<String> items(String chooser) {
        Combo c = d.pane().choosers().get(chooser);
        assertTrue(c != null, "no chooser '" + chooser + "'; choosers: " + d.pane().choosers().keySet() + ", fields: "
                + d.pane().fields().keySet());
        return List.of(c.getItems());
    }

    /** Picks {@code item} from chooser {@code chooser} as a click in its list does. */
    private static void pick(String chooser, String item) {
        Combo c = d.pane().choosers().get(chooser);
        c.select(c.indexOf(item));
        c.notifyListeners(SWT.Selection, new Event());
    }

    @Test
    void theInputsListTheScriptsGroupsAutomataStatesAndBehaviors() {
        d.pane().palette().full(true);
        d.pane().palette().choose("Behavior");
        assertEquals(List.of("step", "swing"), items("automaton"));
        assertTrue(items("group").containsAll(List.of("leftLift", "leftSwing", "rightLift", "rightSwing", "spine")),
                "groups: " + items("group"));
        assertTrue(d.pane().fields().containsKey("behavior"), "a new behavior's name is typed");
        d.pane().palette().choose("Instance");
        assertEquals(List.of("walk"), items("behavior"));
        d.pane().palette().choose("Automaton");
        assertEquals(List.of("lower", "push", "raise", "reach", "stance"), items("add state"));
        pick("add state", "raise");
        pick("add state", "stance");
        assertEquals("raise, stance", d.pane().choosers().get("add state").getText(), "picked states make a list in order");
        d.press("Add automaton", "name", "hop", "times", "1, 1");
        assertTrue(d.text().contains("<hop states=\"raise, stance\" times=\"1, 1\"/>"), d.text());
    }

    @Test
    void theStatesInputIsNamedInTheUsersLanguage() {
        // It read "add state:" in every language: the input's key was shown as its name. The
        // attributes' names before the other inputs are PARSL and stay as the file writes them.
        Locale before = Lang.current();
        try {
            Lang.use(Locale.GERMAN);
            d.pane().palette().full(true);
            d.pane().palette().choose(PanelMsg.PALETTE_AUTOMATON.text());
            assertEquals("Zustand hinzufügen:", nameBefore(d.pane().choosers().get("add state")));
            assertEquals("times:", nameBefore(d.pane().fields().get("times")));
        } finally {
            Lang.use(before);
            d.pane().palette().full(true);
        }
    }

    /** The text of the label the edit row puts before {@code input}. */
    private static String nameBefore(Control input) {
        assertTrue(input != null, "no such input; fields: " + d.pane().fields().keySet() + ", choosers: "
                + d.pane().choosers().keySet());
        Control[] row = input.getParent().getChildren();
        int i = Arrays.asList(row).indexOf(input);
        return ((Label) row[i - 1]).getText();
    }

    @Test
    void theBeginnerPaletteHasAnAutomatonButton() {
        d.pane().palette().full(false);
        assertEquals(List.of("Pose", "Gait table", "Automaton", "Behavior"), d.pane().palette().items());
    }

    @Test
    void aGaitTableIsStartedAsRowsTimesModulesOfZerosAndShown() {
        d.pane().palette().full(false);
        d.pane().palette().choose("Gait table");
        assertEquals("4", d.pane().fields().get("rows").getText(), "four rows to start with");
        assertEquals("55", d.pane().fields().get("modules").getText(), "one column per module of the robot (0..54)");
        assertTrue(d.pane().actions().containsKey("rows+") && d.pane().actions().containsKey("modules\u2212"),
                "rows and modules change with + and \u2212: " + d.pane().actions().keySet());
        d.press("Add gait table", "name", "wave", "rows", "2", "modules", "3");
        assertTrue(d.text().contains("<wave>\n      0, 0, 0\n      0, 0, 0\n    </wave>\n  </automata>"), d.text());
        IdeAccess.pump(() -> IdeAccess.grid(ide).visible() && IdeAccess.grid(ide).table() != null && "wave".equals(IdeAccess.grid(ide).table().name()),
                "the grid beside the text to show the new table");
        IdeAccess.pump(() -> d.pane().current() && d.pane().shown().view() == View.RING
                && "wave".equals(d.pane().shown().subject()), "the diagram to show the new table's rows");
    }

    @Test
    void afterAddTheViewShowsWhatWasAdded() {
        d.pane().palette().full(true);
        d.pane().palette().choose("Automaton");
        d.press("Add automaton", "name", "hop", "add state", "raise, stance", "times", "1, 1");
        IdeAccess.pump(() -> d.pane().current() && d.pane().shown().view() == View.RING
                && "hop".equals(d.pane().shown().subject()), "the ring of the new automaton");
        assertFalse(d.pane().actions().containsKey("Add automaton"), "the palette's inputs close: the ring's own show");
        d.pane().palette().choose("Behavior");
        d.press("Add behavior", "behavior", "hopping", "automaton", "hop", "group", "spine", "time", "");
        IdeAccess.pump(() -> d.pane().current() && d.pane().shown().view() == View.LANES
                && "hopping".equals(d.pane().shown().subject()), "the lanes of the new behavior");
        d.pane().palette().choose("Pose");
        d.press("Add pose", "name", "crouch", "angles", "-40");
        assertTrue(d.pane().message().startsWith("Added pose 'crouch'"), d.pane().message());
    }

    @Test
    void labelsCountFirstSecondNotFromZero() {
        d.show(View.PHASE, null);
        assertEquals(List.of("walk, first: swing on !leftSwing", "walk, second: swing on rightSwing",
                "walk, third: step on leftLift", "walk, fourth: step on rightLift"), d.pane().shown().subjects());
        d.show(View.LANES, "walk");
        assertTrue(d.pane().shown().scene().shapes().stream().anyMatch(s -> s instanceof Scene.Text t
                && t.text().equals("behavior walk  (as the first <main> entry runs it)")), "the lanes' title");
    }

    @Test
    void thePalettesInputsCloseWhenAnotherFileIsOpened() throws Exception {
        d.pane().palette().choose("Pose");
        assertTrue(d.pane().actions().containsKey("Add pose"));
        Path other = home.resolve("scripts").resolve("other.xml");
        Files.writeString(other, original.replace("<program>", "<!-- another file -->\n<program>"));
        IdeAccess.open(ide, other);
        d.caughtUp();
        assertFalse(d.pane().actions().containsKey("Add pose"), "the pose's inputs stayed open into the next file: "
                + d.pane().actions().keySet());
        IdeAccess.open(ide, home.resolve("scripts").resolve("centipede-walk.xml"));
        d.caughtUp();
    }
}
