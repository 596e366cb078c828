package org.parpe.gui.pose;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.load.LoadResult;
import org.parpe.core.model.Program;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.serial.record.PoseRecording;

class ScriptInsertTest {
    static final String LEGS = """
            <?xml version="1.0"?>
            <!-- two legs; </automata> in a comment must not be taken for the section's end -->
            <program>
              <robot>
                <structure>
                  <leg elements="0, 1"/>
                  <leftLeg elements="2, 3"/>
                  <rightLeg elements="4, 5"/>
                </structure>
              </robot>
              <automata/>
              <states>
                <rec_leg angles="0"/>
                <play_leg angles="10"/>
              </states>
            </program>
            """;

    static Program load(String text) {
        LoadResult r = ScriptDocument.load(Path.of("legs.xml"), text, Map.of());
        assertNotNull(r.program(), "does not load: " + r.diagnostics() + "\n" + text);
        assertTrue(r.errors().isEmpty(), r.errors() + "\n" + text);
        return r.program();
    }

    static PoseRecording legPoses() {
        PoseRecording r = new PoseRecording("leg", new int[] {0, 1});
        r.add(new double[] {30, 0}, 1);
        r.add(new double[] {30, -40}, 1);
        r.add(new double[] {-30, -40}, 2);
        return r;
    }

    @Test
    void writesAnAutomatonABehaviorAndAMainThatRunWithThePhaseDelay() {
        String text = LEGS.replace("<automata/>", "<automata>\n    <wave states=\"rec_leg\"/>\n  </automata>");
        Program before = load(text);
        ScriptInsert.Request req = new ScriptInsert.Request(legPoses(), List.of("leftLeg", "rightLeg"), 2, 0, 0.25);
        assertNull(ScriptInsert.check(before, req));
        ScriptInsert.Result r = ScriptInsert.insert(text, before, req);
        assertEquals("rec_leg_2", r.automaton(), "rec_leg is a state's name already");
        assertEquals("play_leg_2", r.behavior(), "play_leg is a state's name already");
        assertTrue(r.mainAdded());
        Program after = load(r.text());
        assertTrue(after.automaton("rec_leg_2").orElseThrow().table());
        assertEquals(3, after.automaton("rec_leg_2").orElseThrow().states().size());
        Traces t = Traces.run(after, 6);
        // rightLeg lags leftLeg by 0.25 cycle of 2 s: it is where leftLeg was 0.5 s before.
        for (double time = 2.0; time <= 5.5; time += 0.37) {
            double now = Math.round(time * 100) / 100.0;
            assertEquals(t.at(2, now - 0.5), t.at(4, now), 1e-6, "module 4 at " + now);
            assertEquals(t.at(3, now - 0.5), t.at(5, now), 1e-6, "module 5 at " + now);
        }
        assertFalse(t.at(2, 3.0) == t.at(4, 3.0) && t.at(2, 3.5) == t.at(4, 3.5), "the groups move in step");
    }

    @Test
    void aSelfClosingSectionIsOpenedAndCommentsAreLeftAlone() {
        Program before = load(LEGS);
        ScriptInsert.Result r = ScriptInsert.insert(LEGS, before,
                new ScriptInsert.Request(legPoses(), List.of("leftLeg"), 4, 0.5, 0));
        assertTrue(r.text().contains("<!-- two legs; </automata> in a comment"), r.text());
        assertFalse(r.text().contains("<automata/>"), r.text());
        assertTrue(r.text().contains("<rec_leg_2 group=\"leftLeg\" period=\"4\" phase=\"0.5\" offset=\"0\"/>"), r.text());
        load(r.text());
    }

    @Test
    void refusesGroupsOfAnotherSizeOrSharingModules() {
        Program p = load(LEGS.replace("<rightLeg elements=\"4, 5\"/>", "<rightLeg elements=\"4, 5\"/>\n<both elements=\"2, 3, 4\"/>"
                + "\n<again elements=\"3, 4\"/>"));
        String size = ScriptInsert.check(p, new ScriptInsert.Request(legPoses(), List.of("both"), 2, 0, 0));
        assertTrue(size != null && size.contains("has 3 modules"), size);
        String shared = ScriptInsert.check(p, new ScriptInsert.Request(legPoses(), List.of("leftLeg", "again"), 2, 0, 0));
        assertTrue(shared != null && shared.contains("share module 3"), shared);
        String period = ScriptInsert.check(p, new ScriptInsert.Request(legPoses(), List.of("leftLeg"), 0, 0, 0));
        assertTrue(period != null && period.contains("period"), period);
    }

    /**
     * Issue 23, item 10: with entries in {@code <main>}, "Use on another group" wrote a behavior
     * that {@code <main>} never played, and said so only as "add it to main". Now it plays first,
     * for three cycles, then what {@code <main>} had; or, when asked not to, main is left alone and
     * the sentence says that the script does not play it.
     */
    @Test
    void aMainWithEntriesPlaysTheNewBehaviorFirstThenItsOwn() {
        String text = LEGS.replace("<automata/>", "<automata>\n    <wave states=\"rec_leg\"/>\n  </automata>\n"
                + "  <behaviors>\n    <still>\n      <wave group=\"leg\" period=\"1\"/>\n    </still>\n  </behaviors>\n"
                + "  <main>\n    <still/>\n  </main>");
        Program before = load(text);
        ScriptInsert.Result r = ScriptInsert.insert(text, before, new ScriptInsert.Request(legPoses(), List.of("leftLeg"), 2, 0, 0));
        assertEquals(ScriptInsert.Main.FIRST, r.main());
        assertTrue(r.text().contains("<main>\n    <play_leg_2 time=\"6\"/>\n    <still/>\n  </main>"), r.text());
        assertTrue(r.said(List.of("leftLeg")).endsWith("<main> now plays it first, for 6 s, then the entries it had."),
                r.said(List.of("leftLeg")));
        Traces t = Traces.run(load(r.text()), 8);
        boolean moved = false;
        for (double time = 0.5; time < 6; time += 0.5) {
            moved |= t.at(2, time) != 0;
        }
        assertTrue(moved, "leftLeg plays the poses while <main>'s first entry runs");
        assertEquals(t.at(2, 6.5), t.at(2, 7.5), 1e-9, "then <still> plays, which does not move leftLeg");

        ScriptInsert.Result left = ScriptInsert.insert(text, before,
                new ScriptInsert.Request(legPoses(), List.of("leftLeg"), 2, 0, 0, false));
        assertEquals(ScriptInsert.Main.UNCHANGED, left.main());
        assertTrue(left.text().contains("<main>\n    <still/>\n  </main>"), left.text());
        assertTrue(left.said(List.of("leftLeg")).contains("the script does not play it yet: add <play_leg_2/> to <main>"),
                left.said(List.of("leftLeg")));
    }
}
