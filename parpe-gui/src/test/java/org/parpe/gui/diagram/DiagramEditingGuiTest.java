package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.jface.fieldassist.ContentProposalAdapter;
import org.eclipse.jface.text.ITextOperationTarget;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableItem;
import org.eclipse.swt.widgets.Text;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.diagram.Projection.View;

/**
 * Editing through the Diagram pane with real widgets, on a copy of
 * {@code examples/centipede-walk.xml}: removing, reordering (buttons and drag) and giving an
 * exit condition and angles to a state on the ring, adding an instance on the lanes and a
 * behavior on the program lane, each by mouse and the edit row only. Each edit changes the
 * text exactly as the same hand edit written out here, and one Undo restores the example byte
 * for byte. The fields offer the editor's content assist.
 */
class DiagramEditingGuiTest {
    private static IdeWindow ide;
    private static DiagramDriver d;
    private static String original;
    private static Path copy;

    private static final String STEP = "<step  states=\"raise, lower, stance\" times=\"0.5, 0.5, 2\"/>";

    @BeforeAll
    static void openWindow() throws Exception {
        Path home = Files.createTempDirectory("parpe-diagram-edit-test");
        copy = Files.createDirectories(home.resolve("scripts")).resolve("centipede-walk.xml");
        Files.copy(Path.of(System.getProperty("parpe.examples", "../examples"), "centipede-walk.xml"), copy);
        original = Files.readString(copy);
        ide = IdeAccess.openIde(home);
        IdeAccess.shell(ide).setSize(1366, 768);
        IdeAccess.open(ide, copy);
        d = new DiagramDriver(ide);
        d.front();
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    @AfterEach
    void textIsBackToTheExample() {
        assertEquals(original, d.text(), "each test leaves the text as it found it");
    }

    private static void undo(String what) {
        IdeAccess.editor(ide).run(ITextOperationTarget.UNDO);
        assertEquals(original, d.text(), "one Undo takes back " + what + " byte for byte");
        d.caughtUp();
    }

    @Test
    void aStateIsMovedByItsButtonsAndRemoved() {
        d.show(View.RING, "step");
        d.click(d.node("<lower "));
        d.press("Later");
        assertEquals(original.replace(STEP, "<step  states=\"raise, stance, lower\" times=\"0.5, 2, 0.5\"/>"), d.text());
        undo("the move");
        d.click(d.node("<lower "));
        d.press("Earlier");
        assertEquals(original.replace(STEP, "<step  states=\"lower, raise, stance\" times=\"0.5, 0.5, 2\"/>"), d.text());
        undo("the move");
        d.click(d.node("<lower "));
        d.press("Remove");
        assertEquals(original.replace(STEP, "<step  states=\"raise, stance\" times=\"0.5, 2\"/>"), d.text());
        IdeAccess.pump(() -> d.pane().shown().ring().arcs().size() == 2, "the ring with two states");
        undo("the removal");
    }

    @Test
    void aStateDraggedOntoAnotherTakesItsPlace() {
        d.show(View.RING, "step");
        d.drag(d.node("<raise "), d.node("<stance "));
        assertEquals(original.replace(STEP, "<step  states=\"lower, stance, raise\" times=\"0.5, 2, 0.5\"/>"), d.text());
        undo("the move");
    }

    @Test
    void aStateGetsAnExitConditionAndNewAngles() {
        d.show(View.RING, "step");
        d.click(d.node("<stance "));
        d.type("exit", "$cycle > 1");
        assertEquals(original.replace(STEP, "<step  states=\"raise, lower, stance\" times=\"0.5, 0.5, 2[$cycle &gt; 1]\"/>"),
                d.text());
        IdeAccess.pump(() -> "$cycle > 1".equals(d.pane().shown().ring().arcs().get(2).exit()), "the exit on the ring");
        undo("the exit condition");
        d.click(d.node("<stance "));
        d.type("angles", "-press / 2");
        assertEquals(original.replace("<stance angles=\"-press\"/>", "<stance angles=\"-press / 2\"/>"), d.text());
        undo("the angles");
    }

    @Test
    void anInstanceIsAddedOnTheLanes() {
        d.show(View.LANES, "walk");
        d.clickAside();
        d.press("Add instance", "automaton", "step", "group", "spine");
        assertEquals(original.replace("period=\"3\"/>\n    </walk>",
                "period=\"3\"/>\n      <step group=\"spine\"/>\n    </walk>"), d.text());
        IdeAccess.pump(() -> d.pane().shown().lanes().lanes().size() == 5, "a fifth lane, the spine");
        undo("the new instance");
    }

    @Test
    void aBehaviorIsAddedOnTheProgramLane() {
        d.show(View.PROGRAM, null);
        d.clickAside();
        d.press("Add behavior", "behavior", "rest", "automaton", "step", "group", "spine", "time", "2");
        assertEquals(original.replace("    <walk/>\n", "    <walk/>\n    <rest time=\"2\"/>\n").replace("    </walk>\n",
                "    </walk>\n    <rest>\n      <step group=\"spine\"/>\n    </rest>\n"), d.text());
        IdeAccess.pump(() -> d.pane().shown().targets().size() == 3, "the program lane with two entries");
        undo("the new behavior");
    }

    @Test
    void anInstanceIsExpandedToAGaitTableInOneUndoableEdit() {
        d.show(View.LANES, "walk");
        d.click(d.node("group=\"rightLift\""));
        d.press("Expand to gait table", "table", "liftTable");
        String t = d.text();
        assertTrue(t.contains("<liftTable  group=\"rightLift\"  offset=\"0\" phase=\"0\" period=\"3\"/>"), t);
        assertTrue(t.contains("<step  states=\"raise, lower, stance\" times=\"0.5, 0.5, 2\"/>\n    <liftTable times=\""), t);
        IdeAccess.pump(() -> IdeAccess.grid(ide).visible() && IdeAccess.grid(ide).table() != null, "the grid editor");
        assertEquals("liftTable", IdeAccess.grid(ide).table().name(), "the new table opens in the grid editor");
        undo("the expansion");
    }

    @Test
    void aGaitTableThatIsAPhaseAutomatonIsMadeOne() throws Exception {
        Path table = copy.resolveSibling("gait-table-12.xml");
        Files.copy(Path.of(System.getProperty("parpe.examples", "../examples"), "gait-table-12.xml"), table);
        String before = Files.readString(table);
        try {
            IdeAccess.open(ide, table);
            d.show(View.LANES, "slither");
            d.click(d.node("<travel group=\"snake\""));
            d.press("Make phase automaton", "automaton", "travelCycle");
            String t = d.text();
            assertTrue(t.contains("<travelCycle group=\"snake\" period=\"4\" phase=\"0.125\"/>"), t);
            assertTrue(t.contains("<travelCycle states=\"travelCycle_0, travelCycle_1, travelCycle_1, travelCycle_1, travelCycle_1,"
                    + " travelCycle_0, travelCycle_0, travelCycle_0\" times=\"1, 1, 1, 1, 1, 1, 1, 1\"/>"), t);
            assertTrue(t.contains("<states>\n    <travelCycle_0 angles=\"15\"/>\n    <travelCycle_1 angles=\"-15\"/>\n  </states>"), t);
            IdeAccess.editor(ide).run(ITextOperationTarget.UNDO);
            assertEquals(before, d.text(), "one Undo takes it back");
        } finally {
            IdeAccess.open(ide, copy);
            d.caughtUp();
        }
    }

    @Test
    void aBadValueIsRefusedWithAMessageAndTheTextStays() {
        d.show(View.PROGRAM, null);
        d.clickAside();
        d.press("Add behavior", "behavior", "walk", "automaton", "step", "group", "spine", "time", "");
        assertEquals(original, d.text());
        assertEquals("a behavior named 'walk' exists already", d.pane().message());
    }

    @Test
    void aPoseBecomesAStatesAnglesByButtonOrByDrop() {
        d.pane().usePoses(() -> "10, -20.5");
        try {
            d.show(View.RING, "step");
            d.click(d.node("<stance "));
            d.press("Use pose");
            assertEquals(original.replace("<stance angles=\"-press\"/>", "<stance angles=\"10, -20.5\"/>"), d.text());
            undo("the pose");
            org.eclipse.swt.graphics.Point at = d.pane().where(d.node("<raise "));
            d.pane().drags().dropPose(at.x, at.y, "5,6");
            d.caughtUp();
            assertEquals(original.replace("<raise  angles=\"lift\"/>", "<raise  angles=\"5,6\"/>"), d.text());
            undo("the dropped pose");
            d.pane().drags().dropPose(at.x, at.y, "<b/>");
            assertEquals(original, d.text(), "dropped text that is not a pose is refused");
            assertTrue(d.pane().message().startsWith("Only a pose"), d.pane().message());
        } finally {
            d.pane().usePoses(() -> null);
        }
    }

    @Test
    void theFieldsOfferTheEditorsWords() {
        d.show(View.RING, "step");
        d.click(d.node("<stance "));
        Text exit = d.pane().fields().get("exit");
        exit.setFocus();
        exit.setText("$cy");
        exit.setSelection(3);
        Event ctrlSpace = new Event();
        ctrlSpace.keyCode = ' ';
        ctrlSpace.character = ' ';
        ctrlSpace.stateMask = SWT.CTRL;
        exit.notifyListeners(SWT.KeyDown, ctrlSpace);
        ContentProposalAdapter adapter = (ContentProposalAdapter) exit.getData("assist");
        IdeAccess.pump(adapter::isProposalPopupOpen, "the proposals");
        List<String> offered = new ArrayList<>();
        IdeAccess.pump(() -> {
            offered.clear();
            for (Shell s : exit.getDisplay().getShells()) {
                collect(s, offered);
            }
            return !offered.isEmpty();
        }, "the proposal list");
        assertTrue(offered.stream().anyMatch(s -> s.startsWith("$cycle")), "offered: " + offered);
        assertTrue(offered.stream().noneMatch(s -> s.startsWith("stride")), "only words with the prefix: " + offered);
        exit.notifyListeners(SWT.KeyDown, escape());
        exit.setText("");
        assertEquals(original, d.text());
    }

    private static Event escape() {
        Event e = new Event();
        e.keyCode = SWT.ESC;
        e.character = SWT.ESC;
        return e;
    }

    private static void collect(org.eclipse.swt.widgets.Composite c, List<String> out) {
        for (var child : c.getChildren()) {
            if (child instanceof Table t) {
                for (TableItem i : t.getItems()) {
                    out.add(i.getText());
                }
            } else if (child instanceof org.eclipse.swt.widgets.Composite k) {
                collect(k, out);
            }
        }
    }
}
