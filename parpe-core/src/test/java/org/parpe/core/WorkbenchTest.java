package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.diagram.BehaviorEdits;
import org.parpe.core.diagram.NodePlaces;
import org.parpe.core.diagram.Scene;
import org.parpe.core.diagram.Workbench;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;

/**
 * The workbench of free nodes and the layout file that keeps their places beside the script
 * (issue 24, item 1): which nodes are free, where a node without a place goes, and how the
 * layout text is written and read, broken and foreign ones included.
 */
class WorkbenchTest {
    /** A script with one behavior run by {@code <main>}, two that are not, and an automaton no behavior plays. */
    static final String SCRIPT = """
            <program>
              <robot>
                <structure>
                  <legs elements="0..3"/>
                  <front elements="0, 1"/>
                  <back elements="2, 3"/>
                </structure>
              </robot>
              <states><up angles="30"/><down angles="-30"/></states>
              <automata>
                <wave states="up, down"/>
                <rest states="down"/>
                <spare states="up, down" times="2, 2"/>
              </automata>
              <main>
                <walk/>
              </main>
              <behaviors>
                <walk><wave group="legs"/></walk>
                <idle><rest group="legs"/></idle>
                <wiggle><wave group="front" phase="0.5"/><rest group="back"/></wiggle>
              </behaviors>
            </program>
            """;

    private static Program load(String text) {
        var r = ScriptLoader.loadText(Path.of("bench.xml"), text, Map.of());
        assertTrue(r.program() != null, r.diagnostics().toString());
        return r.program();
    }

    @Test
    void theFreeNodesAreTheBehaviorsMainDoesNotRunAndTheAutomataNoBehaviorPlays() {
        Program p = load(SCRIPT);
        assertEquals(List.of("idle", "wiggle"), Workbench.freeBehaviors(p).stream().map(Workbench.Node::name).toList());
        assertEquals(List.of("wiggle", "not run by <main>", "wave on front", "rest on back"),
                Workbench.freeBehaviors(p).get(1).lines());
        assertEquals(List.of("spare"), Workbench.freeAutomata(p).stream().map(Workbench.Node::name).toList());
        assertEquals(20, Workbench.freeBehaviors(p).get(0).pos().line(), "the node stands for <idle>'s element");
    }

    @Test
    void aNodeWithoutAPlaceGoesWhereItOverlapsNoOther() {
        Program p = load(SCRIPT);
        List<Workbench.Node> nodes = Workbench.freeBehaviors(p);
        Scene above = new Scene(400, 200);
        // idle put by the user exactly where the first default slot is: wiggle must go elsewhere
        Workbench.Bench free = Workbench.of(above, "bench", nodes, Map.of());
        Workbench.Placed first = free.placed().get(0);
        Workbench.Bench b = Workbench.of(above, "bench", nodes, Map.of("wiggle", new double[] {first.x(), first.y()}));
        Workbench.Placed idle = b.placed().get(0);
        Workbench.Placed wiggle = b.placed().get(1);
        assertEquals(first.x(), wiggle.x());
        assertEquals(first.y(), wiggle.y());
        assertFalse(idle.sceneX() < wiggle.sceneX() + wiggle.w() && wiggle.sceneX() < idle.sceneX() + idle.w()
                && idle.sceneY() < wiggle.sceneY() + wiggle.h() && wiggle.sceneY() < idle.sceneY() + idle.h(),
                "idle at " + idle + " overlaps wiggle at " + wiggle);
        assertTrue(b.top() >= above.height(), "the workbench starts under the drawing");
        assertTrue(idle.sceneY() > b.top() && wiggle.sceneY() > b.top());
        assertEquals(wiggle, b.at(wiggle.sceneX() + 1, wiggle.sceneY() + 1));
        assertArrayEquals(new double[] {0, b.scene().height() - b.top()}, b.clamp(-50, 1e6, 100, 40),
                "dropped far off, a node stays at the workbench's left and bottom edges");
        assertArrayEquals(new double[] {b.scene().width() - 100, 30}, b.clamp(1e6, b.top() - 10, 100, 40),
                "and under its title");
        assertNull(b.at(1, 1), "the drawing above is no node of the workbench");
    }

    @Test
    void aPlaceIsKeptAsGivenAndTheSceneGrowsToHoldIt() {
        Program p = load(SCRIPT);
        Workbench.Bench b = Workbench.of(new Scene(400, 200), "bench", Workbench.freeBehaviors(p),
                Map.of("idle", new double[] {300, 500}));
        Workbench.Placed idle = b.placed().get(0);
        assertEquals(300, idle.x());
        assertEquals(500, idle.y());
        assertEquals(b.top() + 500, idle.sceneY());
        assertTrue(b.scene().height() >= idle.sceneY() + idle.h());
        assertTrue(b.scene().shapes().stream().anyMatch(s -> s instanceof Scene.Rect r && idle.node().pos().equals(r.source())));
    }

    @Test
    void withoutFreeNodesTheDrawingIsUnchanged() {
        Scene above = new Scene(400, 200);
        assertEquals(above, Workbench.of(above, "bench", List.of(), Map.of()).scene());
    }

    @Test
    void aFreeBehaviorDroppedOnTheLaneIsRunByANewLastEntry() {
        Program p = load(SCRIPT);
        String edited = BehaviorEdits.addEntry(SCRIPT, p, "idle").apply(SCRIPT);
        assertEquals(SCRIPT.replace("    <walk/>\n", "    <walk/>\n    <idle/>\n"), edited);
        assertThrows(IllegalArgumentException.class, () -> BehaviorEdits.addEntry(SCRIPT, p, "nothing"));
        String macros = SCRIPT.replace("<idle>", "<idle macros=\"g\">").replace("<rest group=\"legs\"/></idle>",
                "<rest group=\"g\"/></idle>");
        Program withMacros = load(macros);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> BehaviorEdits.addEntry(macros, withMacros, "idle"));
        assertEquals("behavior 'idle' takes macros (g); write its <main> entry with their values in the text", e.getMessage());
    }

    @Test
    void theLayoutTextIsWrittenAndReadBack() {
        NodePlaces n = NodePlaces.NONE.with("program", "idle", 40, 12.25).with("lanes", "spare", 262, 30);
        assertEquals("parpe-layout 1\nprogram idle 40 12.3\nlanes spare 262 30\n", n.format());
        NodePlaces.Read r = NodePlaces.parse("bench.xml.layout", n.format());
        assertTrue(r.ours());
        assertEquals("", r.message());
        assertArrayEquals(new double[] {40, 12.3}, r.places().at("program", "idle"));
        assertEquals(n.format(), r.places().format());
        assertNull(r.places().at("lanes", "idle"), "places are per view");
    }

    @Test
    void retainDropsThePlacesOfNodesThatAreNoLongerFree() {
        NodePlaces n = NodePlaces.NONE.with("program", "idle", 1, 2).with("program", "old", 3, 4).with("lanes", "old", 5, 6);
        NodePlaces kept = n.retain("program", List.of("idle"));
        assertNull(kept.at("program", "old"));
        assertArrayEquals(new double[] {5, 6}, kept.at("lanes", "old"));
        assertTrue(NodePlaces.NONE.with("program", "x", 0, 0).retain("program", List.of()).isEmpty());
        assertThrows(IllegalArgumentException.class, () -> NodePlaces.NONE.with("program", "two words", 0, 0));
    }

    @Test
    void brokenLinesAreLeftOutWithOneMessageNamingTheFirst() {
        String text = "parpe-layout 1\r\nprogram idle 40 12\nprogram wiggle forty 12\n# a comment\n\nlanes spare 1 2 3\n"
                + "program ok -5 1e1\nprogram inf 1 NaN\n";
        NodePlaces.Read r = NodePlaces.parse("bench.xml.layout", text);
        assertTrue(r.ours(), "a layout file with bad lines is still ours: writing it mends it");
        assertArrayEquals(new double[] {40, 12}, r.places().at("program", "idle"));
        assertArrayEquals(new double[] {-5, 10}, r.places().at("program", "ok"));
        assertNull(r.places().at("program", "wiggle"));
        assertNull(r.places().at("lanes", "spare"));
        assertEquals("bench.xml.layout:3: expected VIEW NAME X Y, got \"program wiggle forty 12\" (and 2 more lines);"
                + " those nodes get a free place", r.message());
    }

    @Test
    void aForeignFileIsNotOursAndGivesNoPlaces() {
        for (String foreign : List.of("<layout><node/></layout>", "parpe-layout 2\nprogram idle 1 2\n",
                "program idle 1 2\n", "\u0000\u0001binary")) {
            NodePlaces.Read r = NodePlaces.parse("bench.xml.layout", foreign);
            assertFalse(r.ours(), foreign);
            assertTrue(r.places().isEmpty());
            assertTrue(r.message().startsWith("bench.xml.layout is not a PARPE layout file"), r.message());
        }
        NodePlaces.Read empty = NodePlaces.parse("bench.xml.layout", "");
        assertTrue(empty.ours(), "an empty file is written over");
        assertEquals("", empty.message());
    }
}
