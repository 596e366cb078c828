package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.diagram.Ring;
import org.parpe.core.diagram.Scene;
import org.parpe.core.run.Breakpoints;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.diagram.Projection.View;
import org.parpe.gui.run.LiveStates;

/**
 * The live overlay of the ring finds each state's arc through the index its layout made, not by
 * matching what the shapes stand for: an automaton that visits one state twice
 * ({@code states="up, down, up, down"}, PARSL.md §6) has two arcs of the same state definition,
 * and a module in the first {@code up} gets its dot, and a breakpoint on the first {@code up} its
 * red mark, on the first arc only. Real widgets under Xvfb; frames made by hand with the indices
 * the engine publishes (entry, instance, state).
 */
class DiagramOverlayIndexGuiTest {
    private static final String TWICE = """
            <?xml version="1.0" ?>
            <program>
              <robot>
                <structure>
                  <chain elements="1..4" />
                </structure>
              </robot>
              <main>
                <sway />
              </main>
              <behaviors>
                <sway>
                  <bob group="chain" phase="0" period="4" />
                </sway>
              </behaviors>
              <automata>
                <bob states="up, down, up, down" times="1, 1, 1, 1" />
              </automata>
              <states>
                <up angles="30" />
                <down angles="-30" />
              </states>
            </program>
            """;

    private static IdeWindow ide;

    @BeforeAll
    static void openWindow() throws Exception {
        Path home = Files.createTempDirectory("parpe-diagram-index-test");
        ide = DiagramWindow.open(home).ide();
        Path twice = home.resolve("scripts").resolve("bob-twice.xml");
        Files.writeString(twice, TWICE);
        IdeAccess.open(ide, twice);
        IdeAccess.pump(() -> pane().current() && pane().program() != null && pane().shown().text().equals(TWICE),
                "the bob-twice script");
        DiagramWindow.show(ide, View.RING, "bob");
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    private static DiagramPane pane() {
        return IdeAccess.diagram(ide);
    }

    /** Module 1 (index 0) in state {@code k} of bob, half through it; the other modules nowhere. */
    private static LiveStates.Frame frame(int k) {
        return new LiveStates.Frame(1, 7, 0, new int[] {1, 2, 3, 4}, new int[] {0, -1, -1, -1}, new int[] {k, -1, -1, -1},
                new double[] {0.5, -1, -1, -1});
    }

    /** Where on the ring (fraction of a turn, 0 at the top, clockwise) the overlay's sector {@code s} is. */
    private static double turn(Scene.Sector s) {
        Scene.Sector ring = pane().shown().scene().shapes().stream()
                .filter(x -> x instanceof Scene.Sector c && c.source() != null).map(x -> (Scene.Sector) x).findFirst().orElseThrow();
        double f = Math.atan2(s.cx() - ring.cx(), -(s.cy() - ring.cy())) / (2 * Math.PI);
        return f - Math.floor(f);
    }

    /** The overlay's sectors drawn as dots of radius {@code r} (progress: 3, breakpoint: 7). */
    private static List<Scene.Sector> dots(double r) {
        return pane().live().overlaid().stream().filter(x -> x instanceof Scene.Sector c && c.r0() == 0 && c.r1() == r)
                .map(x -> (Scene.Sector) x).toList();
    }

    @Test
    void aModuleInTheFirstVisitOfAStateIsDrawnOnTheFirstArc() {
        List<Ring.Arc> arcs = pane().shown().ring().arcs();
        assertEquals(List.of("up", "down", "up", "down"), arcs.stream().map(Ring.Arc::state).toList());
        assertEquals(arcs.get(0).pos(), arcs.get(2).pos(), "both ups are the one state definition");
        for (int k : new int[] {0, 2}) {
            pane().drawFrame(frame(k));
            int[] counts = new int[4];
            counts[k] = 1;
            assertEquals(Arrays.toString(counts), Arrays.toString(pane().live().counts()));
            List<Scene.Sector> progress = dots(3);
            assertEquals(1, progress.size(), "one module, one dot");
            double at = turn(progress.get(0));
            Ring.Arc arc = arcs.get(k);
            assertEquals(arc.from() + 0.5 * (arc.to() - arc.from()), at, 1e-6, "the dot half through arc " + k);
        }
    }

    @Test
    void aBreakpointOnTheFirstVisitIsMarkedOnTheFirstArcOnly() {
        Ring.Arc first = pane().shown().ring().arcs().get(0);
        Point at = pane().where(first.pos());
        assertNotNull(at, "the arc of up is drawn");
        Event click = new Event();
        click.button = 1;
        click.x = at.x;
        click.y = at.y;
        pane().canvas().notifyListeners(SWT.MouseDown, click);
        button("Break on entry").notifyListeners(SWT.Selection, new Event());
        try {
            assertEquals(java.util.Set.of(new Breakpoints.Point("bob", 0, Breakpoints.Kind.ENTER)),
                    IdeAccess.controller(ide).breakpoints().points());
            pane().drawFrame(frame(1));
            List<Scene.Sector> red = dots(7);
            assertEquals(1, red.size(), "one breakpoint, one mark");
            assertEquals(first.from() + 0.01, turn(red.get(0)), 1e-6, "at the start of the first arc");
        } finally {
            button("Clear entry break").notifyListeners(SWT.Selection, new Event());
        }
        assertEquals(java.util.Set.of(), IdeAccess.controller(ide).breakpoints().points());
    }

    private static Button button(String text) {
        return Arrays.stream(all(pane().control())).filter(c -> c instanceof Button b && b.getText().equals(text))
                .map(c -> (Button) c).findFirst().orElseThrow(() -> new AssertionError("no button '" + text + "'"));
    }

    private static Control[] all(Control c) {
        if (!(c instanceof Composite k)) {
            return new Control[] {c};
        }
        return Arrays.stream(k.getChildren()).flatMap(x -> Arrays.stream(all(x))).toArray(Control[]::new);
    }
}
