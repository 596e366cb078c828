package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.eclipse.jface.text.ITextOperationTarget;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.SourcePos;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.diagram.Projection.View;

/**
 * The Diagram pane with real widgets on a copy of {@code examples/centipede-walk.xml}: every
 * view draws; a click on a node selects exactly its element in the editor and the caret in the
 * text selects its node; a value typed into a node's field and confirmed with Enter changes the
 * text exactly as the same edit made by hand (written out here, not computed by the code under
 * test) and one Undo brings back the original byte for byte. Saves a picture of the window with
 * each view at 1366×768 to {@code docs/images/ide/diagram-VIEW.png} (folder: system property
 * {@code parpe.ideImages}) for docs/ide.md.
 */
class DiagramGuiTest {
    private static IdeWindow ide;
    private static String original;
    private static Path copy;
    private static Path home;

    @BeforeAll
    static void openWindow() throws Exception {
        home = Files.createTempDirectory("parpe-diagram-test");
        DiagramWindow.Opened o = DiagramWindow.open(home);
        ide = o.ide();
        copy = o.copy();
        original = Files.readString(copy);
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    @AfterEach
    void textIsBackToTheExample() {
        assertEquals(original, text(), "each test leaves the text as it found it");
    }

    private static DiagramPane pane() {
        return IdeAccess.diagram(ide);
    }

    private static String text() {
        return IdeAccess.editor(ide).document().get();
    }

    private static void show(View v, String subject) {
        DiagramWindow.show(ide, v, subject);
    }

    /** A left click on the canvas where {@code node} is drawn, as the mouse sends it. */
    private static void click(SourcePos node) {
        Point p = pane().where(node);
        assertNotNull(p, node + " is not drawn");
        mouse(SWT.MouseDown, p);
    }

    /** A left-button mouse event of {@code type} at {@code at} on the canvas. */
    private static void mouse(int type, Point at) {
        new DiagramDriver(ide).mouse(type, at);
    }

    /** Drags with the left button from {@code from} to {@code to}, as the mouse does. */
    private static void drag(Point from, Point to) {
        mouse(SWT.MouseDown, from);
        mouse(SWT.MouseMove, new Point((from.x + to.x) / 2, (from.y + to.y) / 2));
        mouse(SWT.MouseMove, to);
        mouse(SWT.MouseUp, to);
    }

    /** The node whose element starts on the line that holds {@code needle}. */
    private static SourcePos node(String needle) {
        return new DiagramDriver(ide).node(needle);
    }

    private static int lineOf(String needle) {
        return new DiagramDriver(ide).lineOf(needle);
    }

    /** Types {@code value} into the selected node's field {@code name} and presses Enter. */
    private static void type(String name, String value) {
        DiagramDriver.enter(pane(), name, value);
    }

    private static void undoRestoresTheOriginal() {
        IdeAccess.editor(ide).run(ITextOperationTarget.UNDO);
        assertEquals(original, text(), "one Undo restores the text byte for byte");
        IdeAccess.pump(() -> pane().current(), "the diagram of the restored text");
    }

    private static void picture(View v) throws Exception {
        DiagramWindow.picture(ide, "diagram-" + v.name().toLowerCase(java.util.Locale.ROOT) + ".png");
    }

    @Test
    void everyViewDrawsTheOpenDocument() throws Exception {
        show(View.PROGRAM, null);
        picture(View.PROGRAM);
        show(View.LANES, "walk");
        assertEquals(5, pane().shown().targets().size(), "a bar per instance of walk, and the behavior itself (its Add instance)");
        picture(View.LANES);
        show(View.RING, "step");
        assertEquals(java.util.List.of("swing", "step"), pane().shown().subjects());
        picture(View.RING);
        show(View.PHASE, "walk, second: swing on rightSwing");
        assertEquals(lineOf("<swing group=\"rightSwing\""), pane().selected().line(), "the phase view selects its instance");
        picture(View.PHASE);
        show(View.GAIT, null);
        picture(View.GAIT);
        assertEquals("", pane().message(), "nothing left out of the gait, nothing to click");
    }

    @Test
    void clickingABarSelectsItsElementAndTheCaretSelectsTheNode() {
        show(View.LANES, "walk");
        SourcePos bar = node("<swing group=\"rightSwing\"");
        click(bar);
        Point sel = IdeAccess.editor(ide).viewer().getSelectedRange();
        assertEquals(new Point(bar.span().start(), bar.span().end() - bar.span().start()), sel);
        assertEquals("<swing group=\"rightSwing\" offset=\"0.5\" phase=\"0.75\" period=\"3\"/>",
                text().substring(sel.x, sel.x + sel.y));
        assertEquals(bar, pane().selected());
        assertEquals("0.75", pane().fields().get("phase").getText());

        int inStep = text().indexOf("rightLift\"  offset");
        IdeAccess.editor(ide).widget().setSelection(inStep);
        IdeAccess.settle();
        assertEquals(lineOf("<step  group=\"rightLift\""), pane().selected().line(), "the caret's instance is selected");
        assertEquals("0.5", pane().fields().get("offset").getText());
    }

    @Test
    void retimingAStateIsOneUndoableEdit() {
        show(View.RING, "step");
        int lower = text().indexOf("<lower");
        IdeAccess.editor(ide).widget().setSelection(lower + 3);
        IdeAccess.settle();
        assertEquals(lineOf("<lower  angles"), pane().selected().line(), "the caret in <lower> selects its arc");
        assertEquals("0.5", pane().fields().get("duration").getText());
        type("duration", "0.75");
        assertEquals(original.replace("<step  states=\"raise, lower, stance\" times=\"0.5, 0.5, 2\"/>",
                "<step  states=\"raise, lower, stance\" times=\"0.5, 0.75, 2\"/>"), text());
        IdeAccess.pump(() -> pane().current(), "the ring of the new text");
        assertEquals("0.75", pane().fields().get("duration").getText(), "the arc stays selected with its new time");
        undoRestoresTheOriginal();
    }

    /**
     * Issue 24: at 1366×768 the rows of controls above the drawing (view, palette, the selected
     * state's fields, breakpoints, lines) left the ring a strip of about 180 of the tab's 450
     * pixels, its labels unreadable; the drawing must get at least half of the tab.
     */
    @Test
    void theDrawingGetsHalfTheTabWithAStateSelected() {
        show(View.RING, "step");
        click(pane().shown().ring().arcs().get(1).pos());
        IdeAccess.settle();
        assertEquals(lineOf("<lower  angles"), pane().selected().line(), "a state is selected");
        assertNotNull(pane().fields().get("duration"), "its fields are shown");
        DiagramWindow.canvasHasHalfTheTab(ide);
    }

    @Test
    void changingAPhaseAndAnOffsetAreOneUndoableEditEach() {
        show(View.PHASE, "walk, third: step on leftLift");
        type("offset", "0.25");
        assertEquals(original.replace("<step  group=\"leftLift\"   offset=\"0\"   phase",
                "<step  group=\"leftLift\"   offset=\"0.25\"   phase"), text());
        undoRestoresTheOriginal();

        show(View.LANES, "walk");
        click(node("<swing group=\"!leftSwing\""));
        type("phase", "-0.25");
        assertEquals(original.replace("<swing group=\"!leftSwing\" offset=\"0\"   phase=\"0.75\"",
                "<swing group=\"!leftSwing\" offset=\"0\"   phase=\"-0.25\""), text());
        undoRestoresTheOriginal();
    }

    @Test
    void anEntryGetsATimeItDidNotHave() {
        show(View.PROGRAM, null);
        click(node("<walk/>"));
        assertEquals("", pane().fields().get("time").getText());
        type("time", "4");
        assertEquals(original.replace("<main>\n    <walk/>", "<main>\n    <walk time=\"4\"/>"), text());
        undoRestoresTheOriginal();
    }

    @Test
    void whatTheRingCannotDrawIsATextIslandThatOpensItsLine() throws Exception {
        // a duration set by a slider is known only while running (as in parpe-cli's island.xml)
        Path island = home.resolve("scripts").resolve("island.xml");
        Files.writeString(island, """
                <?xml version="1.0"?>
                <program>
                  <robot><structure><body elements="0..5"/></structure></robot>
                  <controls><hold type="slider" min="0.5" max="3" value="1"/></controls>
                  <main><go/></main>
                  <behaviors><go><wave group="body" phase="0.1" period="2"/></go></behaviors>
                  <automata>
                    <wave states="up, down, rest"
                          times="1, 1, $hold"/>
                  </automata>
                  <states><up angles="30"/><down angles="-30"/><rest angles="0"/></states>
                </program>
                """);
        try {
            IdeAccess.open(ide, island);
            show(View.RING, "wave");
            assertTrue(pane().message().contains("1 thing the view cannot draw"), pane().message());
            SourcePos at = pane().shown().scene().shapes().stream()
                    .map(s -> s instanceof org.parpe.core.diagram.Scene.Rect r ? r.source() : null)
                    .filter(p -> p != null && p.span() == null).findFirst().orElseThrow();
            click(at);
            int caretLine = IdeAccess.editor(ide).widget().getLineAtOffset(IdeAccess.editor(ide).viewer().getSelectedRange().x) + 1;
            assertEquals(lineOf("times=\"1, 1, $hold\""), caretLine, "the island opens the text at its line");
        } finally {
            IdeAccess.open(ide, copy);
            IdeAccess.pump(() -> pane().current(), "the centipede again");
        }
    }

    @Test
    void draggingOnThePhaseWheelSetsThePhase() {
        show(View.PHASE, "walk, second: swing on rightSwing");
        // offset 0.5: module 1's tick goes to 0.6 of a turn when the phase is 0.1
        Point from = pane().drags().onWheel(0.25);
        Point to = pane().drags().onWheel(0.6);
        drag(from, to);
        assertEquals(original.replace("<swing group=\"rightSwing\" offset=\"0.5\" phase=\"0.75\"",
                "<swing group=\"rightSwing\" offset=\"0.5\" phase=\"0.1\""), text());
        undoRestoresTheOriginal();
    }

    @Test
    void theLiveOverlayShowsTheStatesTheEngineIsIn() throws Exception {
        live(View.RING, "step");
    }

    @Test
    void theLiveOverlayShowsTheBarsDrivingModules() throws Exception {
        live(View.LANES, "walk");
    }

    /**
     * Runs the centipede and checks ten frames of the overlay on {@code view} against the same
     * program's engine run headless to each frame's tick: on the ring of step, the lift modules
     * per state; on the lanes of walk, the modules each instance drives.
     */
    private static void live(View view, String subject) throws Exception {
        show(view, subject);
        DiagramWindow.tenFrames(ide, () -> pane().live().counts() != null, tick -> {
            int[] counts = pane().live().counts();
            // The same program's engine, run headless to that tick: which state is each leg's lift in?
            org.parpe.core.run.Engine e = new org.parpe.core.run.Engine(IdeAccess.program(ide), org.parpe.core.run.RunOptions.defaults());
            e.start();
            while (e.tick() < tick) {
                e.step();
            }
            int n = e.moduleIds().length;
            int[] inst = new int[n];
            int[] state = new int[n];
            e.moduleStates(inst, state);
            int[] expected = new int[view == View.RING ? 3 : 4];
            for (int m = 0; m < n; m++) {
                if (view == View.LANES && inst[m] >= 0) {
                    expected[inst[m]]++;
                } else if (inst[m] == 2 || inst[m] == 3) {
                    // instances 2 and 3 of walk run "step" (on leftLift and rightLift)
                    expected[state[m]]++;
                }
            }
            assertEquals(view == View.RING ? 14 : 28, java.util.Arrays.stream(expected).sum(),
                    view == View.RING ? "the 14 lift modules run step" : "the 28 leg modules are driven");
            assertEquals(java.util.Arrays.toString(expected), java.util.Arrays.toString(counts), "modules per state at tick " + tick);
        }, "diagram-live-" + view.name().toLowerCase(java.util.Locale.ROOT) + ".png");
    }

    @Test
    void draggingAnEntryOntoAnotherReordersMain() throws Exception {
        Path standup = home.resolve("scripts").resolve("standup-walk.xml");
        Files.copy(Path.of(System.getProperty("parpe.examples", "../examples"), "standup-walk.xml"), standup);
        String before = Files.readString(standup);
        try {
            IdeAccess.open(ide, standup);
            show(View.PROGRAM, null);
            Point from = pane().where(node("<standup time=\"10\"/>"));
            Point to = pane().where(node("<walk/>"));
            drag(from, to);
            assertEquals(before.replace("<main>\n    <standup time=\"10\"/>\n    <walk/>", "<main>\n    <walk/>\n    <standup time=\"10\"/>"),
                    text());
            IdeAccess.editor(ide).run(ITextOperationTarget.UNDO);
            assertEquals(before, text(), "one Undo restores the order byte for byte");
        } finally {
            IdeAccess.open(ide, copy);
            IdeAccess.pump(() -> pane().current(), "the centipede again");
        }
    }

    @Test
    void aStateAddedOnTheRingIsDefinedAndTimedInOneUndoableEdit() {
        show(View.RING, "swing");
        mouse(SWT.MouseDown, new Point(0, 0));
        assertEquals(null, pane().selected(), "a click on no node selects none: the automaton's fields show");
        type("add state", "hop");
        assertEquals(original.replace("<swing states=\"reach, push\" times=\"1, 2\"/>",
                "<swing states=\"reach, push, hop\" times=\"1, 2, 1\"/>").replace("<stance angles=\"-press\"/>",
                "<stance angles=\"-press\"/>\n    <hop angles=\"0\"/>"), text());
        IdeAccess.pump(() -> pane().current() && pane().shown().ring().arcs().size() == 3, "the ring with three states");
        undoRestoresTheOriginal();
    }
}
