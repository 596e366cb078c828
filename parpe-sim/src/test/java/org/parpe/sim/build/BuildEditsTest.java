package org.parpe.sim.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.sim.config.Kit;
import org.parpe.sim.config.PartType;

/** Builder edits that are refused and why, closing a loop, numbering modules, and undo/redo. */
class BuildEditsTest {
    private static final String TEE = """
            <robot-config>
              <part name="body" type="node"/>
              <part name="t0" type="segment" id="0"/>
              <part name="arm" type="segment" id="1"/>
              <connect from="body.1" to="t0.0"/>
              <connect from="body.2" to="arm.0"/>
            </robot-config>
            """;

    private static RobotDraft tee() {
        return RobotDraft.of("tee.xml", TEE);
    }

    @Test
    void aKitRefusesWhatItDoesNotHave() {
        Kit kit = Kit.of("class.xml", Map.of(PartType.SEGMENT, 3, PartType.NODE, 1));
        RobotDraft d = tee();
        assertEquals(Map.of(PartType.SEGMENT, 1, PartType.NODE, 0, PartType.FOOT, 0, PartType.HUB, 0), d.left(kit));
        assertEquals("the kit has no foot left (it has 0 feet)", d.add("t0", 1, PartType.FOOT, 0, 0, 8, kit).refusal());
        RobotDraft three = d.apply(d.add("t0", 1, PartType.SEGMENT, 0, 0, 8, kit));
        assertEquals("the kit has no segment left (it has 3 segments)",
                three.add("arm", 1, PartType.SEGMENT, 0, 0, 8, kit).refusal());
    }

    @Test
    void anIdInUseAPlateTakenAndTheRootAreRefusedSayingWhy() {
        RobotDraft d = tee();
        assertEquals("ID 0 is used by t0", d.setModuleId("arm", 0).refusal());
        assertEquals("'arm' has ID 1 already", d.setModuleId("arm", 1).refusal());
        assertEquals("plate body.1 is taken (body.1 to t0.0, line 5)", d.add("body", 1, PartType.FOOT, 0, 0, 8, null).refusal());
        assertEquals("'body' (node) has plates 0..5, not 6", d.add("body", 6, PartType.FOOT, 0, 0, 8, null).refusal());
        assertEquals("'body' hangs on no plate (it is a root); turn a part that hangs on it", d.turn("body", 1).refusal());
        assertEquals("'body' is the root and 2 parts hang on it; make another part the root first", d.remove("body").refusal());
        assertEquals("'body' is a node; only segments have module IDs, angles and limp", d.setAngle("body", 5).refusal());
        assertEquals("an initial angle is within -90..90 degrees, not 91", d.setAngle("t0", 91).refusal());
        assertEquals("there is no part 'x'", d.remove("x").refusal());
        assertEquals("a hub has 3..16 plates, not 2", d.add("t0", 1, PartType.HUB, 0, 0, 2, null).refusal());
        assertThrows(IllegalArgumentException.class, () -> d.apply(d.remove("body")));
    }

    @Test
    void aLoopClosesWhereThePlatesMeetWithTheOrientationThatLinesThemUp() {
        RobotDraft loop = RobotDraft.fromGenerator("loop.xml", "loop");
        String closing = "\n  <connect from=\"s5.1\" to=\"s0.0\"/>";
        RobotDraft open = RobotDraft.of("loop.xml", loop.text().replace(closing, ""));
        assertTrue(open.problems().isEmpty(), open.problems().toString());
        assertTrue(open.gap("s5", 1, "s0", 0) < 1e-6, "the ends of the generator's loop meet");
        BuildEdit e = open.closeLoop("s5", 1, "s0", 0);
        assertEquals("Close the loop s5.1 – s0.0", e.description());
        assertEquals(loop.text(), e.edit().apply(open.text()), "the same text as the generator's loop");
    }

    @Test
    void aLoopThatDoesNotMeetIsRefusedWithTheDistanceAndTheAngle() {
        RobotDraft snake = RobotDraft.fromGenerator("snake.xml", "snake:n=6");
        double gap = snake.gap("s5", 1, "s0", 0);
        assertEquals(String.format(Locale.ROOT, "plates %.1f mm and 0.0 degrees apart; they must meet within 3 mm and 3"
                + " degrees", gap * 1000), snake.closeLoop("s5", 1, "s0", 0).refusal());
        assertTrue(gap > 0.3, "six segments end to end: " + gap);
        assertEquals("plate s0.1 is taken (s0.1 to s1.0, line 10)", snake.closeLoop("s0", 1, "s5", 1).refusal());
        assertTrue(Double.isNaN(snake.gap("s0", 7, "s5", 1)));
    }

    @Test
    void assignIdsNumbersTheSegmentsInChainOrderAsOneEdit() {
        RobotDraft d = RobotDraft.of("t.xml", """
                <robot-config>
                  <part name="body" type="node"/>
                  <part name="left" type="segment" id="7"/>
                  <part name="t1" type="segment" id="2"/>
                  <part name="t0" type="segment" id="5"/>
                  <connect from="body.1" to="t0.0"/>
                  <connect from="body.2" to="left.0"/>
                  <connect from="t0.1" to="t1.0"/>
                </robot-config>
                """);
        BuildEdit e = d.assignIds();
        // depth first from the root, each part's connections in file order: the tail t0, t1, then the arm
        assertEquals(d.text().replace("id=\"7\"", "id=\"2\"").replace("\"t1\" type=\"segment\" id=\"2\"", "\"t1\" type=\"segment\" id=\"1\"")
                .replace("id=\"5\"", "id=\"0\""), e.edit().apply(d.text()));
        assertEquals(3, e.edit().replacements().size());
        RobotDraft after = d.apply(e);
        assertEquals("the IDs are in chain order already", after.assignIds().refusal());
    }

    @Test
    void removingAPartOfALoopKeepsWhatTheOtherWayRoundStillHolds() {
        RobotDraft loop = RobotDraft.fromGenerator("loop.xml", "loop");
        BuildEdit e = loop.remove("s3");
        assertEquals("Remove s3", e.description());
        RobotDraft after = loop.apply(e);
        assertEquals(java.util.List.of("s0", "s1", "s2", "s4", "s5"), after.partNames());
        assertTrue(after.problems().isEmpty(), after.problems().toString());
    }

    @Test
    void historyUndoesAndRedoesOneStepPerEdit() {
        BuildHistory h = new BuildHistory();
        assertFalse(h.canUndo());
        assertNull(h.undoLabel());
        RobotDraft d0 = RobotDraft.empty("h.xml");
        BuildEdit first = d0.first(PartType.SEGMENT, 8);
        RobotDraft d1 = d0.apply(first);
        h.push(d0.text(), d1.text(), first.description());
        BuildEdit add = d1.add("s0", 1, PartType.FOOT, 0, 0, 8, null);
        RobotDraft d2 = d1.apply(add);
        h.push(d1.text(), d2.text(), add.description());
        assertEquals("Add foot foot0 on s0.1", h.undoLabel());
        assertEquals(d1.text(), h.undo());
        assertEquals("Add foot foot0 on s0.1", h.redoLabel());
        assertEquals(d0.text(), h.undo());
        assertFalse(h.canUndo());
        assertEquals(d1.text(), h.redo());
        BuildEdit turn = d1.setAngle("s0", 30);
        h.push(d1.text(), turn.edit().apply(d1.text()), turn.description());
        assertFalse(h.canRedo(), "a new edit forgets what could be redone");
        assertEquals("Set the angle of s0 to 30°", h.undoLabel());
        h.clear();
        assertFalse(h.canUndo());
        assertThrows(IllegalStateException.class, h::undo);
    }
}
