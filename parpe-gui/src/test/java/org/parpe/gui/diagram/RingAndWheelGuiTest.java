package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.List;
import java.util.Map;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.diagram.Scene;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.diagram.Projection.View;

/**
 * Issue 31, item 2: at 1366×768 the ring drew "T = …" over the angles and said "ΣT", and the phase
 * wheel labelled its ticks with module IDs while its text spoke of positions; dragging the
 * wheel's hand left the hand where it was. Now every text of both drawings, as painted on the
 * canvas (its extent in the canvas's own font), meets no other; the ring says "one cycle" and
 * "lasts"; the ticks are numbered by position; the dragged hand follows the mouse and shows where
 * the ticks go. Real widgets under Xvfb, the window at 1366×768 and larger; screenshots in
 * {@code target/gui-test-artefacts}.
 */
class RingAndWheelGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        IdeAccess.closeIde(ide);
    }

    private DiagramPane open(int width, int height) throws Exception {
        ide = DiagramWindow.open(Files.createTempDirectory("parpe-ring")).ide();
        IdeAccess.shell(ide).setBounds(0, 0, width, height);
        IdeAccess.settle();
        return IdeAccess.diagram(ide);
    }

    /** The texts painted on the canvas now, after a paint of the whole drawing. */
    private List<Map.Entry<Rectangle, String>> painted(DiagramPane pane) {
        pane.canvas().redraw();
        pane.canvas().update();
        IdeAccess.settle();
        List<Map.Entry<Rectangle, String>> texts = pane.drawnTexts();
        assertFalse(texts.isEmpty(), "the drawing has texts");
        return texts;
    }

    private static void noOverlap(List<Map.Entry<Rectangle, String>> texts) {
        for (int i = 0; i < texts.size(); i++) {
            for (int j = i + 1; j < texts.size(); j++) {
                Rectangle a = texts.get(i).getKey();
                Rectangle b = texts.get(j).getKey();
                assertFalse(a.intersects(b), "'" + texts.get(i).getValue() + "' " + a + " and '" + texts.get(j).getValue()
                        + "' " + b + " overlap");
            }
        }
    }

    private static List<String> words(List<Map.Entry<Rectangle, String>> texts) {
        return texts.stream().map(Map.Entry::getValue).toList();
    }

    @Test
    void atLaptopSizeTheRingsLabelsMeetNoOtherAndSpeakInWords() throws Exception {
        DiagramPane pane = open(1366, 768);
        DiagramWindow.show(ide, View.RING, "step");
        var texts = painted(pane);
        noOverlap(texts);
        List<String> w = words(texts);
        assertTrue(w.contains("one cycle") && w.contains("3 s"), "the cycle in words: " + w);
        assertTrue(w.contains("lasts 0.5 s") && w.contains("lasts 2 s"), "each state's duration in words: " + w);
        assertTrue(w.stream().noneMatch(s -> s.contains("\u03a3") || s.startsWith("T =")), "no symbols: " + w);
        IdeAccess.screenshot(IdeAccess.shell(ide), "ring-1366x768.png");

        DiagramWindow.show(ide, View.PHASE, "walk, second: swing on rightSwing");
        texts = painted(pane);
        noOverlap(texts);
        w = words(texts);
        // rightSwing is modules 14, 16, …, 26; phase 0.75, offset 0.5: positions 0 and 4 start half a cycle late.
        // Positions 0 and 1 always keep their labels; another is left out where it would meet a label already placed.
        assertTrue(w.contains("0, 4") && w.contains("1, 5"), "ticks numbered by position: " + w);
        assertTrue(w.stream().noneMatch(s -> s.contains("14, 22")), "no tick named by module ID: " + w);
        assertTrue(w.stream().anyMatch(s -> s.contains("position i")), "the text speaks of positions too: " + w);
        IdeAccess.screenshot(IdeAccess.shell(ide), "wheel-1366x768.png");
    }

    @Test
    void onALargeScreenTheLabelsMeetNoOtherEither() throws Exception {
        DiagramPane pane = open(1600, 1000);
        DiagramWindow.show(ide, View.RING, "step");
        noOverlap(painted(pane));
        IdeAccess.screenshot(IdeAccess.shell(ide), "ring-large.png");
        DiagramWindow.show(ide, View.PHASE, "walk, third: step on leftLift");
        noOverlap(painted(pane));
        IdeAccess.screenshot(IdeAccess.shell(ide), "wheel-large.png");
    }

    private void viewMenu(String item) {
        var view = java.util.Arrays.stream(IdeAccess.shell(ide).getMenuBar().getItems()).filter(i -> i.getText().equals("&View"))
                .findFirst().orElseThrow().getMenu();
        java.util.Arrays.stream(view.getItems()).filter(i -> i.getText().replace("&", "").startsWith(item)).findFirst()
                .orElseThrow().notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
        IdeAccess.settle();
    }

    private static int smallest(List<Map.Entry<Rectangle, String>> texts) {
        return texts.stream().mapToInt(e -> e.getKey().height).min().orElseThrow();
    }

    @Test
    void viewZoomInMakesTheDiagramsTextLargerAndItsLabelsStillMeetNoOther() throws Exception {
        DiagramPane pane = open(1366, 768);
        DiagramWindow.show(ide, View.RING, "step");
        int normal = smallest(painted(pane));
        for (int i = 0; i < 4; i++) {
            viewMenu("Zoom In");
        }
        var ring = painted(pane);
        assertTrue(smallest(ring) >= normal * 3 / 2, "the smallest text grew from " + normal + " to " + smallest(ring) + " px");
        noOverlap(ring);
        IdeAccess.screenshot(IdeAccess.shell(ide), "ring-zoomed-1366x768.png");
        DiagramWindow.show(ide, View.PHASE, "walk, second: swing on rightSwing");
        noOverlap(painted(pane));
        viewMenu("Reset Zoom");
        DiagramWindow.show(ide, View.RING, "step");
        assertEquals(normal, smallest(painted(pane)), "Reset Zoom: the text is as it was");
    }

    /** Where the dragged hand points, as a fraction of a turn from the top, clockwise. */
    private static double handAt(DiagramPane pane) {
        double[] c = null;
        for (Scene.Shape s : pane.shown().scene().shapes()) {
            if (s instanceof Scene.Sector k && k.source() == null && k.from() == 0 && k.to() == 1) {
                c = new double[] {k.cx(), k.cy()};
            }
        }
        for (Scene.Shape s : pane.drags().preview()) {
            if (s instanceof Scene.Line l && c != null && l.x1() == c[0] && l.y1() == c[1]) {
                double f = Math.atan2(l.x2() - l.x1(), -(l.y2() - l.y1())) / (2 * Math.PI);
                return f < 0 ? f + 1 : f;
            }
        }
        throw new AssertionError("no hand is drawn while dragging: " + pane.drags().preview());
    }

    @Test
    void theDraggedHandFollowsTheMouseAndPreviewsTheDelays() throws Exception {
        DiagramPane pane = open(1366, 768);
        DiagramDriver d = new DiagramDriver(ide);
        DiagramWindow.show(ide, View.PHASE, "walk, second: swing on rightSwing");
        String before = d.text();
        // phase 0.75, offset 0.5: position 1's tick, where the hand points, is at 0.25 of a turn
        Point from = pane.drags().onWheel(0.25);
        d.mouse(SWT.MouseDown, from);
        d.mouse(SWT.MouseMove, pane.drags().onWheel(0.6));
        assertEquals(0.6, handAt(pane), 0.01, "the hand is where the mouse is");
        assertTrue(pane.message().contains("phase=\"0.1\"") && pane.message().contains("start 0.5, 0.6, 0.7, 0.8"),
                "the new phase and the delays it gives: " + pane.message());
        IdeAccess.screenshot(IdeAccess.shell(ide), "wheel-drag-1366x768.png");
        d.mouse(SWT.MouseMove, pane.drags().onWheel(0.9));
        assertEquals(0.9, handAt(pane), 0.01, "the hand follows the mouse");
        assertTrue(pane.message().contains("phase=\"0.4\""), pane.message());
        assertEquals(before, d.text(), "nothing is written while dragging");
        d.mouse(SWT.MouseUp, pane.drags().onWheel(0.9));
        assertTrue(pane.drags().preview().isEmpty(), "the preview goes when the mouse is released");
        assertEquals(before.replace("<swing group=\"rightSwing\" offset=\"0.5\" phase=\"0.75\"",
                "<swing group=\"rightSwing\" offset=\"0.5\" phase=\"0.4\""), d.text());
    }
}
