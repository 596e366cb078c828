package org.parpe.sim.world;

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

/** World files: what they define, rubble from a seed, and every problem of a bad one at FILE:LINE:COL. */
class WorldReaderTest {
    @TempDir
    Path dir;

    private Path file(String name, String text) throws IOException {
        Path f = dir.resolve(name);
        Files.writeString(f, text);
        return f;
    }

    private List<String> errors(Path f) {
        DiagnosticList d = new DiagnosticList();
        assertNull(WorldReader.read(f, d));
        return d.all().stream().map(Diagnostic::format).toList();
    }

    /**
     * Issue 32, trial changes: every kind of movable object is read and built as itself (a kind
     * that {@code Movables} does not build fails here, not silently as another), and the
     * "expected …" message names it.
     */
    @Test
    void everyMovableKindIsBuiltAsItselfAndNamedInTheMessage() throws IOException {
        for (Movables.Kind k : Movables.Kind.values()) {
            Path f = file(k.xml() + ".xml", "<world>\n  <" + k.xml() + " name=\"o\" x=\"0\" y=\"0\"/>\n</world>\n");
            DiagnosticList d = new DiagnosticList();
            World w = WorldReader.read(f, d);
            assertNotNull(w, k + ": " + d.all());
            assertEquals(List.of(k.xml()), w.objects().stream().map(World.MovableObject::kind).toList());
        }
        String message = errors(file("u.xml", "<world>\n  <nothing/>\n</world>\n")).get(0);
        for (Movables.Kind k : Movables.Kind.values()) {
            assertTrue(message.contains("<" + k.xml() + ">"), message);
        }
    }

    /** docs/simulator.md documents every element the reader knows (issue 32, trial changes: a new kind is documented). */
    @Test
    void everyElementIsDocumented() throws IOException {
        String doc = Files.readString(Path.of("../docs/simulator.md"));
        List<String> missing = WorldReader.ELEMENTS.stream().filter(e -> !doc.contains("`<" + e)).toList();
        assertEquals(List.of(), missing, "elements docs/simulator.md does not describe");
    }

    @Test
    void aWorldDefinesItsSceneryRegionsAndScoring() throws IOException {
        Path f = file("w.xml", """
                <world time-limit="45" floor-friction="0.5">
                  <start x="0.1" y="0.2" yaw="90"/>
                  <arena x0="-1" y0="-1" x1="3" y1="1"/>
                  <wall x0="0" y0="0.3" x1="2" y1="0.3" height="0.1"/>
                  <ramp x="1" y="0" length="0.5" width="0.4" slope="10" friction="0.8"/>
                  <step x="2" y="0" length="0.3" width="0.4" height="0.02"/>
                  <cylinder x="-0.5" y="0" radius="0.05" height="0.2"/>
                  <chip name="chip1" x="0.5" y="0"/>
                  <cup name="cup" x="0.5" y="0.5"/>
                  <lever name="handle" x="1" y="0.5" turn="right"/>
                  <zone name="finish" x0="2.5" y0="-1" x1="3" y1="1"/>
                  <checkpoint x0="1" y0="-1" x1="1.2" y1="1"/>
                  <goal zone="finish" points="100" per-second-left="2"/>
                  <path-score points-per-metre="10"/>
                  <deliver zone="finish" objects="chip"/>
                  <press lever="handle"/>
                  <disqualify tilt="80" leave-arena="true"/>
                </world>
                """);
        DiagnosticList d = new DiagnosticList();
        World w = WorldReader.read(f, d);
        assertNotNull(w, d.all().toString());
        assertEquals(45, w.timeLimit());
        assertEquals(0.5, w.floorFriction());
        assertEquals(new World.Start(0.1, 0.2, 0, 90, 0), w.start());
        assertEquals(4, w.solids().size());
        assertEquals(0.8, w.solids().get(1).friction());
        assertEquals(0.5, w.solids().get(0).friction(), "a solid's friction defaults to the floor's");
        World.Solid wall = w.solids().get(0);
        assertEquals(1, wall.position().x(), 1e-12);
        assertEquals(0.05, wall.position().z(), 1e-12, "a wall stands on the floor");
        // the ramp's top face starts at the floor at x = 1 and rises 10 degrees
        World.Solid ramp = w.solids().get(1);
        double topZ = ramp.position().z() + ramp.rotation().m22() * 0.025;
        assertEquals(0.25 * Math.sin(Math.toRadians(10)), topZ, 1e-9);
        assertEquals(List.of("chip", "cup", "lever"), w.objects().stream().map(World.MovableObject::kind).toList());
        assertEquals(13, w.objects().get(1).pieces().size(), "a cup is a base and twelve wall boards");
        assertEquals(-1, w.levers().get(0).axis().z(), "turn=right: clockwise seen from above");
        assertEquals(2, w.scoring().goal().perSecondLeft());
        assertEquals(80, w.scoring().maxTiltDeg());
        assertTrue(w.scoring().leaveArena());
        assertEquals(1, w.checkpoints().size());
    }

    @Test
    void rubbleIsTheSamePileForTheSameSeedAndAnotherForAnother() throws IOException {
        String pile = "<world><rubble x0=\"0\" y0=\"-0.5\" x1=\"2\" y1=\"0.5\" count=\"50\" seed=\"%d\""
                + " min-size=\"0.02\" max-size=\"0.06\"/></world>";
        World a = WorldReader.read(file("a.xml", pile.formatted(7)), new DiagnosticList());
        World b = WorldReader.read(file("b.xml", pile.formatted(7)), new DiagnosticList());
        World c = WorldReader.read(file("c.xml", pile.formatted(8)), new DiagnosticList());
        assertEquals(50, a.solids().size());
        assertEquals(a.solids(), b.solids());
        assertTrue(!a.solids().equals(c.solids()));
        for (World.Solid s : a.solids()) {
            assertTrue(s.position().x() >= 0 && s.position().x() <= 2 && Math.abs(s.position().y()) <= 0.5, s.toString());
        }
    }

    @Test
    void aMalformedWorldGetsEveryProblemAtItsPlace() throws IOException {
        Path f = file("bad.xml", """
                <world time-limit="-3">
                  <start x="0" y="0" yaw="north"/>
                  <box x="1" y="0" length="0.2" width="0.2"/>
                  <ramp x="1" y="0" length="1" width="0.5" slope="75"/>
                  <zone name="finish" x0="2" y0="1" x1="1" y1="2"/>
                  <tower x="1"/>
                  <chip name="c" x="0" y="0" colour="red"/>
                  <goal zone="finnish"/>
                  <rubble x0="0" y0="0" x1="1" y1="1" count="5" min-size="0.1" max-size="0.05"/>
                </world>
                """);
        String name = f.toString();
        assertEquals(List.of(
                name + ":1:1: error: time-limit must be in 0.01..1000000, got -3",
                name + ":2:3: error: yaw must be a number, got 'north'",
                name + ":3:3: error: <box> needs the attribute 'height'",
                name + ":4:3: error: slope must be in 0.10..60, got 75",
                name + ":5:3: error: a region needs x0 < x1 and y0 < y1, got x0=2 x1=1 y0=1 y1=2",
                name + ":6:3: error: unknown element <tower>; expected <start>, <arena>, <box>, <step>, <ramp>, <wall>,"
                        + " <cylinder>, <rubble>, <chip>, <ball>, <cup>, <lever>, <zone>, <checkpoint>, <goal>,"
                        + " <path-score>, <deliver>, <press> or <disqualify>",
                name + ":7:3: error: <chip> has no attribute 'colour'; it takes friction, mass, name, radius,"
                        + " thickness, x, y",
                name + ":9:3: error: max-size must be >= min-size (0.1), got 0.05",
                name + ":8:3: error: no <zone> is called 'finnish'; expected one of finish"), errors(f));
    }

    @Test
    void notXmlAWrongRootAndHugeFilesAreRefusedWithTheirPlace() throws IOException {
        Path broken = file("broken.xml", "<world>\n  <box x=\"1\"\n</world>\n");
        List<String> e = errors(broken);
        assertEquals(1, e.size(), e.toString());
        assertTrue(e.get(0).startsWith(broken + ":3:"), e.toString());
        assertTrue(e.get(0).contains("not well-formed XML"), e.toString());
        Path config = file("robot.xml", "<robot-config><part name=\"s\" type=\"segment\" id=\"0\"/></robot-config>\n");
        assertTrue(errors(config).get(0).contains("robot.xml:1:1: error: <robot-config> is not a world file"),
                errors(config).toString());
        Path big = dir.resolve("big.xml");
        Files.write(big, new byte[(16 << 20) + 1]);
        assertTrue(errors(big).get(0).contains("larger than the limit of 16 MiB"), errors(big).toString());
    }

    /**
     * Issue 31 item 5: {@code <cup radius="1e-9">} or {@code <chip radius="1e-9">} ended in
     * ODE4j's mass assertion (an internal error, exit 4). Every size and mass has a range,
     * reported at its element like the robot configuration's numbers.
     */
    @Test
    void sizesAndMassesOutOfRangeAreLocatedErrors() throws IOException {
        Path f = file("tiny.xml", """
                <world>
                  <cup name="cup" x="0" y="0" radius="1e-9"/>
                  <chip name="chip" x="1" y="0" radius="1e-9" thickness="0"/>
                  <ball name="ball" x="2" y="0" mass="1e-9"/>
                  <lever name="lever" x="3" y="0" length="0.0001" mass="2000"/>
                  <box x="4" y="0" length="1e-9" width="0.1" height="0.1"/>
                  <cup name="flat" x="5" y="0" radius="1" height="0.002"/>
                  <rubble x0="0" y0="0" x1="1" y1="1" count="0"/>
                </world>
                """);
        String name = f.toString();
        assertEquals(List.of(
                name + ":2:3: error: radius must be at least 0.001 m (1 mm), got 1e-9",
                name + ":3:3: error: thickness must be at least 0.001 m (1 mm), got 0",
                name + ":3:3: error: radius must be at least 0.001 m (1 mm), got 1e-9",
                name + ":4:3: error: mass must be at least 0.001 kg (1 g), got 1e-9",
                name + ":5:3: error: length must be at least 0.001 m (1 mm), got 0.0001",
                name + ":5:3: error: mass must be in 0..1000, got 2000",
                name + ":6:3: error: length must be at least 0.001 m (1 mm), got 1e-9",
                name + ":7:3: error: a cup's height must be more than its base's thickness (0.004 m: 4 mm, or a quarter"
                        + " of the radius when that is less), got 0.002",
                name + ":8:3: error: count must be in 1..2000, got 0"), errors(f));
    }
}
