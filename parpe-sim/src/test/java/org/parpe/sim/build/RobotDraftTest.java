package org.parpe.sim.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.parpe.sim.config.PartType;

/** The draft of a configuration: reading, queries, and the text each edit writes (hand-written expectations). */
class RobotDraftTest {
    private static final String TEE = """
            <?xml version="1.0" ?>
            <!-- a comment stays -->
            <robot-config>
              <part name="body" type="node"/>
              <part name='t0' type="segment" id="0"/>
              <connect from="body.1" to="t0.0" orientation="90"/>
              <root part="body"/>
            </robot-config>
            """;

    private static RobotDraft tee() {
        RobotDraft d = RobotDraft.of("tee.xml", TEE);
        assertTrue(d.problems().isEmpty(), d.problems().toString());
        return d;
    }

    private static String applied(RobotDraft d, BuildEdit e) {
        assertFalse(e.refused(), e.refusal());
        return e.edit().apply(d.text());
    }

    @Test
    void anEmptyDraftHasNoProblemAndNoRobot() {
        RobotDraft d = RobotDraft.empty("new.xml");
        assertEquals("<?xml version=\"1.0\" ?>\n<robot-config>\n</robot-config>\n", d.text());
        assertTrue(d.problems().isEmpty(), d.problems().toString());
        assertNull(d.config());
        assertTrue(d.bodies().isEmpty());
        assertNull(d.root());
    }

    @Test
    void theFirstPartGoesBetweenTheTagsAndBecomesTheRoot() {
        RobotDraft d = RobotDraft.empty("new.xml");
        BuildEdit e = d.first(PartType.NODE, 8);
        assertEquals("<?xml version=\"1.0\" ?>\n<robot-config>\n  <part name=\"node0\" type=\"node\"/>\n</robot-config>\n",
                applied(d, e));
        assertEquals("Start with node node0", e.description());
        RobotDraft after = d.apply(e);
        assertEquals("node0", after.root());
        assertEquals(6, after.freePlates().size());
        assertTrue(after.first(PartType.NODE, 8).refused());
    }

    @Test
    void theFirstPartOfABlankFileWritesTheConfigurationAfterWhatTheFileHolds() {
        RobotDraft d = RobotDraft.of("blank.xml", "<!-- my robot -->\n");
        BuildEdit e = d.first(PartType.HUB, 6);
        assertEquals("<!-- my robot -->\n<robot-config>\n  <part name=\"hub0\" type=\"hub\" plates=\"6\"/>\n</robot-config>\n",
                applied(d, e));
        assertEquals("the file is not a robot configuration yet; mend it first (see Problems)",
                RobotDraft.of("x.xml", "<program/>").first(PartType.NODE, 8).refusal());
    }

    @Test
    void addWritesThePartAfterTheLastPartAndTheConnectionAfterTheLastConnection() {
        RobotDraft d = tee();
        BuildEdit e = d.add("body", 2, PartType.SEGMENT, 0, 1, 8, null);
        assertEquals(TEE.replace("""
                  <part name='t0' type="segment" id="0"/>
                """, """
                  <part name='t0' type="segment" id="0"/>
                  <part name="s0" type="segment" id="1"/>
                """).replace("""
                  <connect from="body.1" to="t0.0" orientation="90"/>
                """, """
                  <connect from="body.1" to="t0.0" orientation="90"/>
                  <connect from="body.2" to="s0.0" orientation="90"/>
                """), applied(d, e));
        assertEquals("Add segment s0 on body.2 turned 90°", e.description());
        RobotDraft after = d.apply(e);
        assertTrue(after.problems().isEmpty(), after.problems().toString());
        assertEquals(List.of("body", "t0", "s0"), after.partNames());
        assertEquals("body.2", after.attachment("s0").orElseThrow().ref());
    }

    @Test
    void attributesAreSetAndDefaultsLeftOut() {
        RobotDraft d = tee();
        assertEquals(TEE.replace(" orientation=\"90\"", ""), applied(d, d.turn("t0", 0)));
        assertEquals(TEE.replace("to=\"t0.0\" orientation=\"90\"", "to=\"t0.0\" orientation=\"180\""), applied(d, d.turn("t0", 2)));
        assertEquals(TEE.replace("id=\"0\"/>", "id=\"7\"/>"), applied(d, d.setModuleId("t0", 7)));
        assertEquals(TEE.replace("id=\"0\"/>", "id=\"0\" angle=\"-22.5\"/>"), applied(d, d.setAngle("t0", -22.5)));
        assertEquals(TEE.replace("id=\"0\"/>", "id=\"0\" limp=\"true\"/>"), applied(d, d.setLimp("t0", true)));
        assertEquals(TEE.replace("<root part=\"body\"/>", "<root part=\"t0\"/>"), applied(d, d.makeRoot("t0")));
        assertEquals(TEE.replace("<root part=\"body\"/>", "<root part=\"body\" roll=\"90\"/>"),
                applied(d, d.setRootPose("roll", 90)));
    }

    @Test
    void removeTakesThePartWhatHangsOnItAndTheirConnections() {
        RobotDraft d = tee();
        assertEquals(TEE.replace("  <part name='t0' type=\"segment\" id=\"0\"/>\n", "")
                .replace("  <connect from=\"body.1\" to=\"t0.0\" orientation=\"90\"/>\n", ""), applied(d, d.remove("t0")));
        BuildEdit root = d.remove("body");
        assertTrue(root.refused());
        assertEquals("'body' is the root and 1 part hang on it; make another part the root first", root.refusal());
    }

    /** "Make editable": the written-out generator robot is the generator's robot, piece for piece. */
    @Test
    void aGeneratorMadeEditableIsTheGeneratorsRobot() {
        for (String spec : List.of("snake:n=12", "snake:n=7,axes=alternate", "loop", "wheel", "wheel:n=5", "centipede",
                "humanoid")) {
            RobotDraft d = RobotDraft.fromGenerator("made.xml", spec);
            assertTrue(d.problems().isEmpty(), spec + ": " + d.problems());
            org.parpe.core.diag.DiagnosticList diags = new org.parpe.core.diag.DiagnosticList();
            var gen = org.parpe.sim.config.RobotConfigs.resolve(spec, new int[0], diags);
            var a = org.parpe.sim.internal.Assembly.build(gen, diags);
            assertEquals(gen.parts().stream().map(p -> p.name() + p.type() + p.moduleId() + p.angle()).toList(),
                    d.config().parts().stream().map(p -> p.name() + p.type() + p.moduleId() + p.angle()).toList(), spec);
            assertEquals(gen.roots().stream().map(r -> List.of(r.part(), r.x(), r.y(), r.roll(), r.pitch(), r.yaw(), r.height()))
                    .toList(), d.config().roots().stream().map(r -> List.of(r.part(), r.x(), r.y(), r.roll(), r.pitch(),
                    r.yaw(), r.height())).toList(), spec);
            assertEquals(a.pieces().size(), d.bodies().size(), spec);
            for (int i = 0; i < a.pieces().size(); i++) {
                var p = a.pieces().get(i);
                var b = d.bodies().get(i);
                assertTrue(org.parpe.sim.geom.Geo.sub(p.position(), b.position()).length() < 1e-9, spec + " " + b);
                assertTrue(org.parpe.sim.geom.Geo.angleBetween(p.rotation(), b.rotation()) < 1e-9, spec + " " + b);
            }
        }
    }
}
