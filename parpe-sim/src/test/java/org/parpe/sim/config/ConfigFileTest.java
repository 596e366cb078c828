package org.parpe.sim.config;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.sim.SimTarget;

/** Configuration files and generator specs: good ones load, bad ones give located messages. */
class ConfigFileTest {
    @TempDir
    Path dir;

    /** Read, generated and assembled as a run does it, so errors of every stage are found. */
    private List<Diagnostic> errors(String name, String text) throws IOException {
        return BadConfigs.runErrors(BadConfigs.write(dir, name, text));
    }

    @Test
    void theExampleConfigurationsLoad() {
        for (String f : List.of("wheel6.xml", "tee-snake.xml", "two-snakes.xml")) {
            DiagnosticList d = new DiagnosticList();
            Path p = Path.of("..", "examples", "configs", f);
            RobotConfig c = RobotConfigs.resolve(p.toString(), new int[0], d);
            assertNotNull(c, d.all().toString());
            assertDoesNotThrow(() -> SimTarget.blueprint(p.toString(), new int[0]));
        }
    }

    @Test
    void unknownPartsPlatesAndOrientationsAreLocated() throws IOException {
        List<Diagnostic> e = errors("bad.xml", """
                <robot-config>
                  <part name="s0" type="segment" id="0"/>
                  <part name="s1" type="segmnt" id="1"/>
                  <connect from="s0.1" to="s2.0" orientation="45"/>
                </robot-config>
                """);
        String all = e.toString();
        assertTrue(all.contains("bad.xml:3:3: error: unknown part type 'segmnt'"), all);
        assertTrue(all.contains("bad.xml:4:3: error: orientation must be 0, 90, 180 or 270"), all);
        String plates = errors("plates.xml", """
                <robot-config>
                  <part name="s0" type="segment" id="0"/>
                  <part name="s1" type="segment" id="0"/>
                  <connect from="s0.7" to="s2.0"/>
                </robot-config>
                """).toString();
        assertTrue(plates.contains("plates.xml:3:3: error: module id 0 is used by two segments"), plates);
        assertTrue(plates.contains("plates.xml:4:3: error: part 's0' (segment) has plates 0..1, got 7"), plates);
        assertTrue(plates.contains("part 's2' is not defined"), plates);
    }

    @Test
    void didYouMeanAndDisconnectedParts() throws IOException {
        List<Diagnostic> e = errors("loose.xml", """
                <robot-config>
                  <part name="head" type="segment" id="0"/>
                  <part name="tail" type="segment" id="1"/>
                  <part name="foot" type="foot"/>
                  <connect from="head.1" to="tial.0"/>
                </robot-config>
                """);
        String all = e.toString();
        assertTrue(all.contains("did you mean 'tail'"), all);
    }

    /** Several roots, one robot each (docs/simulator.md, "Configuration files"): each placed at its own pose. */
    @Test
    void eachRootPlacesARobotOfItsOwn() throws IOException {
        Path f = dir.resolve("two.xml");
        Files.writeString(f, """
                <robot-config>
                  <part name="a" type="segment" id="0"/>
                  <part name="b" type="segment" id="1"/>
                  <root part="a" x="0" y="0"/>
                  <root part="b" x="1" y="0.5" yaw="90"/>
                </robot-config>
                """);
        DiagnosticList d = new DiagnosticList();
        RobotConfig c = RobotConfigs.resolve(f.toString(), new int[0], d);
        assertNotNull(c, d.all().toString());
        assertEquals(List.of("a", "b"), c.roots().stream().map(RootPose::part).toList());
        assertEquals(1.0, c.roots().get(1).x());
        assertDoesNotThrow(() -> SimTarget.blueprint(f.toString(), new int[0]));
    }

    @Test
    void rootsThatShareARobotOrLeaveAPartOutAreLocated() throws IOException {
        String twice = errors("twice.xml", """
                <robot-config>
                  <part name="a" type="segment" id="0"/>
                  <part name="b" type="segment" id="1"/>
                  <connect from="a.1" to="b.0"/>
                  <root part="a"/>
                  <root part="a" x="1"/>
                </robot-config>
                """).toString();
        assertTrue(twice.contains("twice.xml:6:3: error: part 'a' is already a root"), twice);
        String joined = errors("joined.xml", """
                <robot-config>
                  <part name="a" type="segment" id="0"/>
                  <part name="b" type="segment" id="1"/>
                  <part name="c" type="foot"/>
                  <connect from="a.1" to="b.0"/>
                  <root part="a"/>
                  <root part="b" x="1"/>
                </robot-config>
                """).toString();
        assertTrue(joined.contains("joined.xml:3:3: error: part 'b' is a root but is connected to root part 'a'"), joined);
        assertTrue(joined.contains("joined.xml:4:3: error: part 'c' is not connected to the root part 'a' or another root"),
                joined);
    }

    @Test
    void aLoopThatDoesNotFitIsReported() throws IOException {
        List<Diagnostic> e = errors("loop.xml", """
                <robot-config>
                  <part name="a" type="segment" id="0"/>
                  <part name="b" type="segment" id="1"/>
                  <part name="c" type="segment" id="2"/>
                  <connect from="a.1" to="b.0"/>
                  <connect from="b.1" to="c.0"/>
                  <connect from="c.1" to="a.0"/>
                </robot-config>
                """);
        assertEquals(1, e.size(), e.toString());
        assertTrue(e.get(0).toString().startsWith(dir.resolve("loop.xml") + ":6:"), e.toString());
        assertTrue(e.get(0).message().contains("closes a loop but does not fit"), e.toString());
    }

    @Test
    void malformedXmlIsLocated() throws IOException {
        List<Diagnostic> e = errors("broken.xml", "<robot-config>\n  <part name=\"a\" type=\"segment\" id=\"0\">\n</robot-config>\n");
        assertTrue(e.get(0).toString().contains("broken.xml:3:"), e.toString());
        assertTrue(e.get(0).message().startsWith("not well-formed XML"), e.toString());
    }

    @Test
    void generatorSpecsAreChecked() {
        DiagnosticList d = new DiagnosticList();
        assertNull(RobotConfigs.resolve("snake:n=0,axis=parallel", new int[0], d));
        String all = d.all().toString();
        assertTrue(all.contains("n must be in 1..1000, got 0"), all);
        assertTrue(all.contains("no parameter 'axis'") && all.contains("did you mean 'axes'"), all);
        DiagnosticList d2 = new DiagnosticList();
        assertNull(RobotConfigs.resolve("centipeed", new int[0], d2));
        assertTrue(d2.all().toString().contains("did you mean 'centipede'"), d2.all().toString());
    }

    @Test
    void aSnakeSizesItselfFromTheScript() {
        DiagnosticList d = new DiagnosticList();
        assertEquals(7, RobotConfigs.resolve("snake", new int[] {0, 2, 4, 6}, d).moduleIds().length);
    }
}
