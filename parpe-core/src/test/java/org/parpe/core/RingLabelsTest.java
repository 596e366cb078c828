package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.parpe.core.diagram.Diagrams;
import org.parpe.core.diagram.Labels;
import org.parpe.core.diagram.Layouts;
import org.parpe.core.diagram.PhaseWheel;
import org.parpe.core.diagram.Scene;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;

/**
 * Issue 31, item 2: the ring drew "T = …" over the angles and "ΣT" in its centre; the phase wheel
 * named its ticks by module ID while its text spoke of positions. Rings of 1 to 16 states, with
 * exits and long angles, and wheels of 2 to 40 modules, at text scales 1 and 1.6 (a shrunk
 * drawing on a small screen): no text's box meets another's, and the words say what the
 * symbols said.
 */
class RingLabelsTest {

    private static Program ring(int states) {
        StringBuilder names = new StringBuilder();
        StringBuilder times = new StringBuilder();
        StringBuilder defs = new StringBuilder();
        for (int i = 0; i < states; i++) {
            names.append(i == 0 ? "" : ", ").append("state").append(i);
            times.append(i == 0 ? "" : ", ").append(i % 3 == 0 ? "0.25" : "1.5").append(i % 4 == 1 ? "[$time &gt; 3]" : "");
            defs.append("<state").append(i).append(" angles=\"").append(i % 2 == 0 ? "30, -30, 45, 10" : "$k * 2")
                    .append("\"/>");
        }
        String text = "<program><robot><structure><b elements=\"0..3\"/></structure></robot>"
                + "<controls><k type=\"slider\" min=\"0\" max=\"90\" value=\"30\"/></controls>"
                + "<behaviors><go><w group=\"b\"/></go></behaviors>"
                + "<automata><w states=\"" + names + "\" times=\"" + times + "\"/></automata><states>" + defs
                + "</states></program>";
        return ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
    }

    private static List<String> texts(Scene sc) {
        return sc.shapes().stream().filter(s -> s instanceof Scene.Text).map(s -> ((Scene.Text) s).text()).toList();
    }

    private static void noOverlap(Scene sc) {
        List<Scene.Text> texts = new ArrayList<>();
        sc.shapes().stream().filter(s -> s instanceof Scene.Text).forEach(s -> texts.add((Scene.Text) s));
        for (int i = 0; i < texts.size(); i++) {
            for (int j = i + 1; j < texts.size(); j++) {
                assertFalse(Labels.box(texts.get(i)).overlaps(Labels.box(texts.get(j))), "'" + texts.get(i).text() + "' "
                        + Labels.box(texts.get(i)) + " meets '" + texts.get(j).text() + "' " + Labels.box(texts.get(j)));
            }
        }
    }

    @ParameterizedTest(name = "{0} states")
    @ValueSource(ints = {1, 2, 3, 5, 8, 12, 16})
    void theRingsLabelsMeetNoOtherAndSpeakInWords(int states) {
        Program p = ring(states);
        var r = Diagrams.ring(p, p.automata().get(0));
        for (double scale : new double[] {1, 1.6}) {
            Scene sc = Layouts.ring(r, scale);
            noOverlap(sc);
            List<String> t = texts(sc);
            assertTrue(t.contains("one cycle"), t.toString());
            assertTrue(t.stream().noneMatch(s -> s.contains("\u03a3") || s.contains("T =")), t.toString());
            assertTrue(t.stream().anyMatch(s -> s.contains("state0")), "the first state is named: " + t);
        }
        if (states == 3) {
            // 0.25 + 1.5 + 1.5 seconds
            assertTrue(texts(Layouts.ring(r)).contains("3.25 s"), texts(Layouts.ring(r)).toString());
            assertTrue(texts(Layouts.ring(r)).contains("lasts 1.5 s"), texts(Layouts.ring(r)).toString());
        }
    }

    @ParameterizedTest(name = "{0} modules")
    @ValueSource(ints = {2, 3, 7, 12, 40})
    void theWheelsTicksAreNumberedByPositionAndTheirLabelsMeetNoOther(int modules) {
        String text = "<program><robot><structure><b elements=\"100.." + (99 + modules) + "\"/></structure></robot>"
                + "<behaviors><go><w group=\"b\" phase=\"" + (1.0 / modules) + "\" offset=\"0.1\"/></go></behaviors>"
                + "<automata><w states=\"s\" times=\"1\"/></automata><states><s angles=\"20\"/></states></program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
        PhaseWheel w = Diagrams.wheel(p.behaviors().get(0).instances().get(0), p.group("b").orElseThrow());
        for (double scale : new double[] {1, 1.6}) {
            Scene sc = Layouts.wheel(w, scale);
            noOverlap(sc);
            List<String> t = texts(sc);
            assertTrue(t.contains("0") && t.contains("1"), "positions 0 and 1 are always named: " + t);
            assertTrue(t.stream().noneMatch(s -> s.equals("100") || s.equals("101")), "no tick named by module ID: " + t);
            assertTrue(t.stream().anyMatch(s -> s.startsWith("position i lags")), t.toString());
        }
    }

    @ParameterizedTest(name = "phase {0}")
    @ValueSource(doubles = {0.1, 0.3, -0.25})
    void theDragPreviewPutsTheHandWhereTheNewPhasePutsPositionOne(double phase) {
        String text = "<program><robot><structure><b elements=\"0..5\"/></structure></robot>"
                + "<behaviors><go><w group=\"b\" phase=\"0.75\" offset=\"0.5\"/></go></behaviors>"
                + "<automata><w states=\"s\" times=\"1\"/></automata><states><s angles=\"20\"/></states></program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
        PhaseWheel moved = Diagrams.wheel(p.behaviors().get(0).instances().get(0), p.group("b").orElseThrow()).withPhase(phase);
        // PARSL.md §7.1: position k lags offset + k·phase cycles
        for (PhaseWheel.Tick t : moved.ticks()) {
            double d = 0.5 + t.position() * phase;
            assertEquals(d - Math.floor(d), t.delay(), 1e-9);
        }
        Scene.Line hand = Layouts.wheelPreview(moved, 1).stream().filter(s -> s instanceof Scene.Line l && l.width() == 2
                && Math.hypot(l.x2() - l.x1(), l.y2() - l.y1()) > 60).map(s -> (Scene.Line) s).findFirst().orElseThrow();
        double f = Math.atan2(hand.x2() - hand.x1(), -(hand.y2() - hand.y1())) / (2 * Math.PI);
        double want = 0.5 + phase;
        assertEquals(want - Math.floor(want), f - Math.floor(f), 1e-9);
    }
}
