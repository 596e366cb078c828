package org.parpe.sim.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.SimTarget;
import org.parpe.sim.config.PartType;

/**
 * Issue 33: the example robots tee-snake and wheel6 built from an empty file by builder edits
 * only (what the Robot tab's clicks make) are the example robots: the same parts, every body
 * in the same place, and a script run on each gives the same trace byte for byte.
 */
class BuildFromEmptyTest {
    private static final Path CONFIGS = Path.of("../examples/configs");

    @TempDir
    Path dir;

    private static RobotDraft step(RobotDraft d, BuildEdit e) {
        assertFalse(e.refused(), e.refusal());
        RobotDraft next = d.apply(e);
        assertTrue(next.problems().isEmpty(), e.description() + ": " + next.problems());
        return next;
    }

    /** tee-snake.xml: a node, a three-segment tail turned 90°, an arm with a foot on each side bent ∓20°. */
    static RobotDraft teeSnake() {
        RobotDraft d = RobotDraft.empty("tee.xml");
        d = step(d, d.first(PartType.NODE, 8));
        d = step(d, d.add("node0", 1, PartType.SEGMENT, 0, 1, 8, null));
        d = step(d, d.add("s0", 1, PartType.SEGMENT, 0, 0, 8, null));
        d = step(d, d.add("s1", 1, PartType.SEGMENT, 0, 0, 8, null));
        d = step(d, d.add("node0", 2, PartType.SEGMENT, 0, 0, 8, null));
        d = step(d, d.add("node0", 3, PartType.SEGMENT, 0, 0, 8, null));
        d = step(d, d.add("s3", 1, PartType.FOOT, 0, 0, 8, null));
        d = step(d, d.add("s4", 1, PartType.FOOT, 0, 0, 8, null));
        d = step(d, d.setAngle("s3", -20));
        return step(d, d.setAngle("s4", 20));
    }

    /** wheel6.xml: a six-plate hub, a segment on each plate (IDs round the other way), a foot on each, rolled upright. */
    static RobotDraft wheel6() {
        RobotDraft d = RobotDraft.empty("wheel.xml");
        d = step(d, d.first(PartType.HUB, 6));
        for (int plate : new int[] {0, 5, 4, 3, 2, 1}) {
            d = step(d, d.add("hub0", plate, PartType.SEGMENT, 0, 0, 8, null));
        }
        for (int s = 0; s < 6; s++) {
            d = step(d, d.add("s" + s, 1, PartType.FOOT, 0, 0, 8, null));
        }
        return step(d, d.setRootPose("roll", 90));
    }

    private static RobotDraft example(String name) throws IOException {
        Path f = CONFIGS.resolve(name);
        return RobotDraft.of(f.toString(), Files.readString(f));
    }

    private static void assertSameRobot(RobotDraft expected, RobotDraft built) {
        List<SimBody> a = expected.bodies();
        List<SimBody> b = built.bodies();
        assertEquals(a.size(), b.size());
        for (int i = 0; i < a.size(); i++) {
            assertEquals(a.get(i).moduleId(), b.get(i).moduleId(), "body " + i);
            assertEquals(a.get(i).kind(), b.get(i).kind(), "body " + i);
            assertTrue(Geo.sub(a.get(i).position(), b.get(i).position()).length() < 1e-9, a.get(i) + " vs " + b.get(i));
            assertTrue(Geo.angleBetween(a.get(i).rotation(), b.get(i).rotation()) < 1e-9, a.get(i) + " vs " + b.get(i));
        }
        for (int i = 0; i < expected.config().parts().size(); i++) {
            var p = expected.config().parts().get(i);
            var q = built.config().parts().get(i);
            assertEquals(List.of(p.type(), p.moduleId(), p.angle(), p.plates(), p.limp()),
                    List.of(q.type(), q.moduleId(), q.angle(), q.plates(), q.limp()), p.name() + " vs " + q.name());
        }
    }

    private String trace(String script, Path config) throws Exception {
        LoadResult r = ScriptLoader.loadText(Path.of("gait.xml"), script, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        Run.Builder b = Run.builder(r.program(), new RunOptions(0.01, 0, List.of()), new DiagnosticList());
        b.attach(new SimTarget(config.toString()));
        StringWriter out = new StringWriter();
        b.trace(out).duration(3);
        b.build().execute();
        return out.toString();
    }

    private Path write(RobotDraft d, String name) throws IOException {
        Path f = dir.resolve(name);
        Files.writeString(f, d.text());
        return f;
    }

    @Test
    void theTeeSnakeBuiltByEditsIsTheExample() throws Exception {
        RobotDraft built = teeSnake();
        assertSameRobot(example("tee-snake.xml"), built);
        String script = Files.readString(Path.of("../examples/wheel.xml")).replace("0,1,2,3,4,5,6,7", "0,1,2,3,4");
        String expected = trace(script, CONFIGS.resolve("tee-snake.xml"));
        assertTrue(expected.split("\n").length > 300, "three seconds of trace");
        assertEquals(expected, trace(script, write(built, "tee.xml")));
    }

    @Test
    void theWheelBuiltByEditsIsTheExample() throws Exception {
        RobotDraft built = wheel6();
        assertSameRobot(example("wheel6.xml"), built);
        String script = Files.readString(Path.of("../examples/wheel.xml"));
        String expected = trace(script, CONFIGS.resolve("wheel6.xml"));
        assertTrue(expected.split("\n").length > 300, "three seconds of trace");
        assertEquals(expected, trace(script, write(built, "wheel.xml")));
    }
}
