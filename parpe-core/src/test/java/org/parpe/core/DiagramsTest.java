package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.diagram.Diagrams;
import org.parpe.core.diagram.Gait;
import org.parpe.core.diagram.GaitDiagram;
import org.parpe.core.diagram.PhaseWheel;
import org.parpe.core.diagram.ProgramLane;
import org.parpe.core.diagram.Ring;
import org.parpe.core.diagram.Swimlanes;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Program;
import org.parpe.core.run.RunOptions;

/** The diagram model against the scripts and PARSL.md §6–§8, not against itself. */
class DiagramsTest {
    private static Program load(String name) {
        return ScriptLoader.load(Examples.dir().resolve(name), Map.of()).program();
    }

    @Test
    void theProgramLaneListsMainsEntriesWithTheirTimesAndExits() {
        ProgramLane lane = Diagrams.program(load("standup-walk.xml")).orElseThrow();
        assertEquals(List.of("standup", "walk"), lane.steps().stream().map(ProgramLane.Step::behavior).toList());
        assertEquals("10", lane.steps().get(0).time());
        assertEquals(null, lane.steps().get(1).exit());
        assertTrue(Diagrams.program(ScriptLoader.loadText(Path.of("t.xml"),
                "<program><robot><structure><b elements=\"0\"/></structure></robot></program>", Map.of()).program()).isEmpty());
    }

    @Test
    void theCentipedesLanesAreItsFourGroupsWithTheLeftSwingMirrored() {
        Program p = load("centipede-walk.xml");
        Swimlanes s = Diagrams.swimlanes(p, p.behavior("walk").orElseThrow());
        assertEquals(List.of("leftSwing", "rightSwing", "leftLift", "rightLift"),
                s.lanes().stream().map(Swimlanes.Lane::group).toList());
        Swimlanes.Bar left = s.lanes().get(0).bars().get(0);
        assertTrue(left.mirrored());
        assertFalse(s.lanes().get(1).bars().get(0).mirrored());
        assertEquals("0.5", s.lanes().get(1).bars().get(0).offset());
        assertEquals("0.75", left.phase());
        assertEquals("3", left.period());
        assertTrue(s.lanes().stream().allMatch(l -> l.bars().get(0).overlaps().isEmpty()));
        assertEquals(List.of(0, 2, 4, 6, 8, 10, 12), s.lanes().get(0).modules());
    }

    @Test
    void instancesUnderIfThatShareAModuleAreMarkedWithTheModule() {
        String text = "<program><robot><structure><a elements=\"0..3\"/><b elements=\"3..5\"/><c elements=\"6\"/></structure>"
                + "</robot><controls><on type=\"slider\" min=\"0\" max=\"1\" value=\"0\"/></controls>"
                + "<main><go/></main><behaviors><go><w group=\"a\"/><w group=\"c\"/>"
                + "<if cond=\"$on > 0.5\"><w group=\"!b\" phase=\"0.1\"/></if></go></behaviors>"
                + "<automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states></program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
        Swimlanes s = Diagrams.swimlanes(p, p.behaviors().get(0));
        Swimlanes.Bar a = s.lanes().get(0).bars().get(0);
        Swimlanes.Bar b = s.lanes().get(2).bars().get(0);
        assertEquals(List.of(2), a.overlaps());
        assertEquals(3, a.shared());
        assertEquals(List.of(0), b.overlaps());
        assertEquals(List.of("$on > 0.5"), b.conditions());
        assertTrue(b.mirrored());
        assertTrue(s.lanes().get(1).bars().get(0).overlaps().isEmpty());
    }

    /**
     * Issue 38: the words the diagrams draw are in the user's language (PARSL's names stay); before,
     * the lanes and the program lane were English whatever the language. The SVG goldens
     * ({@code DiagramCommandTest}) hold the English.
     */
    @Test
    void theDiagramsWordsAreInTheUsersLanguage() {
        Program p = load("centipede-walk.xml");
        Swimlanes s = Diagrams.swimlanes(p, p.behavior("walk").orElseThrow());
        ProgramLane lane = Diagrams.program(load("standup-walk.xml")).orElseThrow();
        String english = org.parpe.core.diagram.Layouts.lanes(s).svg();
        assertTrue(english.contains(">mirrored (!)<") && english.contains(">7 modules: 0, 2, 4, 6…<"), english);
        org.parpe.core.text.Lang.use(java.util.Locale.GERMAN);
        try {
            String lanes = org.parpe.core.diagram.Layouts.lanes(s).svg();
            assertTrue(lanes.contains(">gespiegelt (!)<") && lanes.contains(">7 Module: 0, 2, 4, 6…<"), lanes);
            assertTrue(lanes.contains(">Verhalten walk"), lanes);
            String program = org.parpe.core.diagram.Layouts.program(lane).svg();
            assertTrue(program.contains(">Zeit 10 s<"), program);
        } finally {
            org.parpe.core.text.Lang.use(java.util.Locale.ENGLISH);
        }
    }

    /** Issue 35: the ring marks the states that arm or release connection plates (PARSL.md §14), in words. */
    @Test
    void theRingSaysWhatAStateDoesToThePlates() {
        String text = "<program><robot><structure><g elements=\"0..3\"/></structure>"
                + "<actuators><latch elements=\"g\"/></actuators></robot><main><b/></main>"
                + "<behaviors><b><w group=\"g\"/></b></behaviors><automata><w states=\"reach, hold, go\"/></automata>"
                + "<states><reach angles=\"30\" latch=\"0, 1\"/><hold angles=\"30\"/><go angles=\"0\" unlatch=\"1\"/></states>"
                + "</program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, java.util.Map.of()).program();
        Ring r = Diagrams.ring(p, p.automaton("w").orElseThrow());
        assertEquals(List.of("latches plates 0, 1", "", "releases plate 1"), r.arcs().stream().map(Ring.Arc::plates).toList());
        String svg = org.parpe.core.diagram.Layouts.ring(r).svg();
        assertTrue(svg.contains(">latches plates 0, 1<") && svg.contains(">releases plate 1<"), svg);
    }

    @Test
    void ringArcsAreProportionalToTheDurations() {
        Ring r = Diagrams.ring(load("centipede-walk.xml"), load("centipede-walk.xml").automaton("step").orElseThrow());
        // times="0.5, 0.5, 2": arcs of 1/6, 1/6 and 2/3 of the circle
        assertEquals(3, r.arcs().size());
        assertEquals(1 / 6.0, r.arcs().get(0).to(), 1e-12);
        assertEquals(2 / 6.0, r.arcs().get(1).to(), 1e-12);
        assertEquals(1.0, r.arcs().get(2).to(), 1e-12);
        assertEquals("stance", r.arcs().get(2).state());
        assertEquals(List.of("-press"), r.arcs().get(2).angles());
        assertTrue(r.islands().isEmpty());
        Program sensor = load("sensor-exit.xml");
        Ring exit = Diagrams.ring(sensor, sensor.automata().get(0));
        assertTrue(exit.arcs().stream().anyMatch(a -> a.exit() != null), "sensor-exit has an exit condition");
    }

    @Test
    void eachStateIsPosedOnTheGroupItIsPlayedOn() {
        String text = "<program><robot><structure><b elements=\"0..2\"/></structure></robot>"
                + "<controls><k type=\"slider\" min=\"0\" max=\"90\" value=\"30\"/></controls>"
                + "<behaviors><go><w group=\"b\"/></go></behaviors>"
                + "<automata><w states=\"bent, per, live\" times=\"1, 1, 1\"/></automata>"
                + "<states><bent angles=\"0, 90, 0\"/><per angles=\"$k + 10 * $index\"/><live angles=\"30 * sin($time)\"/>"
                + "</states></program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
        Ring r = Diagrams.ring(p, p.automata().get(0));
        assertEquals("b", r.group());
        assertEquals(3, r.modules());
        Ring.Arc bent = r.arcs().get(0);
        assertEquals(List.of(0.0, 90.0, 0.0), bent.pose());
        // one angle for the whole group, from a control at its declared value and each module's $index
        assertEquals(List.of(30.0, 40.0, 50.0), r.arcs().get(1).pose());
        assertTrue(r.arcs().get(2).pose().isEmpty(), "an angle known only while running is not posed");
    }

    @Test
    void aPoseOnAMirroredGroupIsNegatedAndCutAfterTwelveModules() {
        String text = "<program><robot><structure><b elements=\"0..19\"/></structure></robot>"
                + "<behaviors><go><w group=\"!b\"/></go></behaviors>"
                + "<automata><w states=\"s\" times=\"1\"/></automata><states><s angles=\"20\"/></states></program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
        Ring r = Diagrams.ring(p, p.automata().get(0));
        assertEquals("!b", r.group());
        assertEquals(20, r.modules());
        assertEquals(Diagrams.POSE_MODULES, r.arcs().get(0).pose().size());
        assertTrue(r.arcs().get(0).pose().stream().allMatch(a -> a == -20.0));
    }


    @Test
    void aDurationKnownOnlyWhileRunningIsATextIsland() {
        String text = "<program><robot><structure><b elements=\"0\"/></structure></robot>"
                + "<controls><t type=\"slider\" min=\"1\" max=\"3\" value=\"1\"/></controls>"
                + "<automata><w states=\"s, s\" times=\"2, $t\"/></automata><states><s angles=\"1\"/></states></program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
        Ring r = Diagrams.ring(p, p.automata().get(0));
        assertEquals(0.5, r.arcs().get(0).to(), 1e-12, "the unknown duration is drawn at the mean of the known ones");
        assertEquals(1, r.islands().size());
        assertEquals(1, r.islands().get(0).pos().line());
        assertTrue(r.islands().get(0).text().contains("$t"));
    }

    @Test
    void theWheelPutsModuleKAtOffsetPlusKPhase() {
        Program p = load("centipede-walk.xml");
        Instance right = p.behavior("walk").orElseThrow().instances().get(1);
        PhaseWheel w = Diagrams.wheel(right, p.group("rightSwing").orElseThrow());
        assertEquals(7, w.ticks().size());
        double[] expected = {0.5, 0.25, 0.0, 0.75, 0.5, 0.25, 0.0}; // frac(0.5 + 0.75 k)
        for (int k = 0; k < 7; k++) {
            assertEquals(expected[k], w.ticks().get(k).delay(), 1e-12);
            assertEquals(14 + 2 * k, w.ticks().get(k).module());
        }
    }

    /**
     * The engine's states against PARSL.md §7.1 worked by hand: module k of a group starts at
     * u = frac(−(offset + k·phase)) and moves dt/period per tick; it is in the state whose part
     * of the nominal cycle holds frac(u).
     */
    @Test
    void theGaitDiagramIsTheStateOfEveryModuleAtEveryTick() {
        Program p = load("centipede-walk.xml");
        double dt = 0.01;
        GaitDiagram g = Gait.record(p, new RunOptions(dt, 0, List.of()), 6);
        assertEquals(601, g.ticks());
        int[][] state = new int[g.moduleIds().length][g.ticks()];
        for (int[] row : state) {
            java.util.Arrays.fill(row, -1);
        }
        for (GaitDiagram.Segment s : g.segments()) {
            for (int t = s.from(); t < s.to(); t++) {
                state[s.row()][t] = s.state();
            }
        }
        // leftSwing (row = module id 0, 2, …): swing, times 1, 2 → reach while frac(u) < 1/3
        // rightLift (15, 17, …): step, times 0.5, 0.5, 2 → raise < 1/6, lower < 2/6, stance
        int checked = 0;
        for (int k = 0; k < 7; k++) {
            for (int t = 1; t < g.ticks(); t++) {
                double u = frac(-(0.75 * k) + t * dt / 3);
                if (near(u, 1 / 3.0) || near(u, 0)) {
                    continue;
                }
                assertEquals(u < 1 / 3.0 ? 0 : 1, state[2 * k][t], "leftSwing module " + 2 * k + " at tick " + t);
                double v = frac(-(0.5 + 0.75 * k) + t * dt / 3);
                if (!near(v, 1 / 6.0) && !near(v, 2 / 6.0) && !near(v, 0)) {
                    assertEquals(v < 1 / 6.0 ? 0 : v < 2 / 6.0 ? 1 : 2, state[15 + 2 * k][t], "rightLift at tick " + t);
                }
                checked++;
            }
        }
        assertTrue(checked > 3000);
        for (int t = 0; t < g.ticks(); t++) {
            assertEquals(-1, state[40][t], "the spine is never driven");
        }
        assertEquals(List.of("reach", "push"), g.legend().get(0).get(0).states());
    }

    private static double frac(double x) {
        return x - Math.floor(x);
    }

    private static boolean near(double u, double boundary) {
        double d = Math.abs(u - boundary);
        return Math.min(d, 1 - d) < 0.011;
    }
}
