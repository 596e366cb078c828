package org.parpe.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.run.RunInfo;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;
import org.parpe.sim.world.WorldScore;

/** Each primitive of a world file acting on a robot: ramps, walls, pushed chips, the lever. */
class WorldPhysicsTest {
    @TempDir
    Path tmp;

    World world(String body) throws IOException {
        Path f = tmp.resolve("w" + System.nanoTime() + ".xml");
        Files.writeString(f, "<world time-limit=\"60\">\n" + body + "\n</world>\n");
        DiagnosticList d = new DiagnosticList();
        World w = WorldReader.read(f, d);
        assertNotNull(w, d.all().toString());
        return w;
    }

    static Simulator started(String spec, World w) {
        Simulator sim = new Simulator(SimTestSupport.config(spec), w);
        sim.start(new RunInfo(null, sim.moduleIds(), 0.01));
        return sim;
    }

    /** The race's travelling wave (lesson 10 with bend 40, period 1.5 s), which crawls towards +x. */
    static void crawl(Simulator sim, int ticks) {
        int n = sim.moduleIds().length;
        double[] cmd = new double[n];
        for (int k = 0; k < ticks; k++) {
            double t = sim.time();
            for (int m = 0; m < n; m++) {
                cmd[m] = 40 * Math.sin(2 * Math.PI * (t / 1.5 - m * 0.2));
            }
            sim.accept(k, t, cmd);
        }
    }

    @Test
    void aSnakeClimbsAFiveDegreeRamp() throws IOException {
        try (Simulator sim = started("snake:n=8",
                world("<ramp x=\"0.6\" y=\"0\" length=\"2\" width=\"0.5\" slope=\"5\"/>"))) {
            double z0 = sim.snapshot().centerOfMass().z();
            crawl(sim, 3000);
            Vec3 com = sim.snapshot().centerOfMass();
            // on the ramp since x = 0.6: at x the ramp's surface is (x − 0.6)·tan 5° high
            assertTrue(com.x() > 1.3, "went up the ramp: " + com);
            assertTrue(com.z() - z0 > 0.6 * (com.x() - 0.6) * Math.tan(Math.toRadians(5)), "rose with the ramp: " + com);
        }
    }

    @Test
    void aSnakeSlidesBackOnAThirtyDegreeRamp() throws IOException {
        try (Simulator sim = started("snake:n=8",
                world("<ramp x=\"0.6\" y=\"0\" length=\"2\" width=\"0.5\" slope=\"30\"/>"))) {
            double best = 0;
            for (int i = 0; i < 30; i++) {
                crawl(sim, 100);
                best = Math.max(best, sim.snapshot().centerOfMass().x());
            }
            Vec3 com = sim.snapshot().centerOfMass();
            assertTrue(best > 0.62, "the head got onto the ramp: best x " + best);
            assertTrue(com.x() < best - 0.05, "slid back from x = " + best + " to " + com);
            assertTrue(com.z() < 0.06, "back at the foot of the ramp: " + com);
        }
    }

    @Test
    void aWallStopsTheSnakeAndTheHeadsTouchSensorReadsIt() throws IOException {
        for (boolean wall : new boolean[] {false, true}) {
            try (Simulator sim = started("snake:n=8",
                    world(wall ? "<wall x0=\"0.9\" y0=\"-0.3\" x1=\"0.9\" y1=\"0.3\" thickness=\"0.02\"/>" : ""))) {
                int touches = 0;
                for (int k = 0; k < 30; k++) {
                    crawl(sim, 100);
                    SensorTable t = sim.readings();
                    touches += (int) t.get(7, Channel.TOUCH_LEFT);
                }
                double x = sim.snapshot().centerOfMass().x();
                if (wall) {
                    // the snake is 0.48 m long; its centre stays about half of that behind the wall
                    assertTrue(x < 0.89 - 0.2, "stopped by the wall at x = 0.89: " + x);
                    assertTrue(touches >= 4, "the head's upper side (touch_left) touched the wall only " + touches + " times");
                } else {
                    assertTrue(x > 1.5, "without the wall it crawls on: " + x);
                    assertEquals(0, touches, "on the open floor the head's upper side touches nothing");
                }
            }
        }
    }

    @Test
    void aPushedChipEndsInTheZoneAndTheScoreCountsIt() throws IOException {
        String scene = """
                <chip name="chip1" x="0.62" y="0" radius="0.03" thickness="0.03"/>
                <zone name="slot" x0="0.8" y0="-0.2" x1="1.05" y1="0.2"/>
                <zone name="elsewhere" x0="0.8" y0="0.5" x1="1.05" y1="0.9"/>
                <deliver zone="slot" objects="chip" points="50"/>
                <deliver zone="elsewhere" objects="chip" points="1000"/>
                """;
        try (Simulator sim = started("snake:n=8", world(scene))) {
            assertEquals(0, sim.metrics().score().delivered(), "not delivered at the start");
            crawl(sim, 2000);
            double[] chip = new double[3];
            sim.objectCentre(0, chip);
            assertTrue(chip[0] > 0.8 && chip[0] < 1.05 && Math.abs(chip[1]) < 0.2, "chip at " + chip[0] + ", " + chip[1]);
            WorldScore s = sim.metrics().score();
            assertEquals(1, s.delivered(), s.toString());
            assertEquals(50, s.score(), 1e-9, s.toString());
        }
    }

    @Test
    void theLeverRegistersAPress() throws IOException {
        String scene = """
                <lever name="handle" x="0.9" y="0.2" yaw="-90" turn="left" height="0.045" length="0.22"
                       press-angle="20" max-angle="60"/>
                <press lever="handle" points="25"/>
                """;
        try (Simulator sim = started("snake:n=8", world(scene))) {
            double most = 0;
            for (int k = 0; k < 40; k++) {
                crawl(sim, 100);
                most = Math.max(most, sim.leverAngle(0));
            }
            WorldScore s = sim.metrics().score();
            assertTrue(most > 20, "the snake turned the lever to " + most + " degrees");
            assertEquals(1, s.presses(), s + ", most " + most);
            assertEquals(25, s.score(), 1e-9);
            assertTrue(sim.leverAngle(0) < 10, "the spring brought it back: " + sim.leverAngle(0));
        }
    }

    /**
     * Issue 31 item 5: the smallest and the largest movable objects the reader takes, at the
     * lightest and heaviest masses, are simulated (the reader's ranges are what ODE can do).
     */
    @Test
    void movableObjectsAtTheEndsOfTheirRangesAreSimulated() throws IOException {
        for (String mass : java.util.List.of("0.001", "1000")) {
            for (String size : java.util.List.of("0.001", "1000")) {
                String m = " mass=\"" + mass + "\"";
                World w = world("<chip name=\"c\" x=\"2\" y=\"0\" radius=\"" + size + "\" thickness=\"" + size + "\"" + m
                        + "/>\n<ball name=\"b\" x=\"2\" y=\"3\" radius=\"" + size + "\"" + m
                        + "/>\n<cup name=\"u\" x=\"2\" y=\"-3\" radius=\"" + size + "\" height=\"" + size + "\"" + m
                        + "/>\n<lever name=\"l\" x=\"-2\" y=\"0\" length=\"" + size + "\" width=\"" + size
                        + "\" thickness=\"" + size + "\"" + m + "/>");
                try (Simulator sim = started("snake:n=4", w)) {
                    crawl(sim, 50);
                    SimSnapshot snap = sim.snapshot();
                    assertEquals(16, snap.scenery().stream().filter(b -> b.kind() == PartKind.OBJECT).count());
                    for (SimBody b : snap.scenery()) {
                        assertTrue(Double.isFinite(b.position().x() + b.position().y() + b.position().z()),
                                "size " + size + ", mass " + mass + ": " + b);
                    }
                }
            }
        }
    }

    /**
     * Issue 31 item 5: ODE4j logs through SLF4J, which without a provider printed three lines to
     * standard error when ODE first reported a problem, before PARPE's own message. A fresh JVM
     * (SLF4J speaks once per JVM) with the test classpath makes ODE fail on an object the reader
     * would refuse (a chip of radius 1e-9 m, built here without the reader): it may throw, but
     * print nothing.
     */
    @Test
    void odeFailuresPrintNoLoggingNoise() throws Exception {
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), Quiet.class.getName()).start();
        String err = new String(p.getErrorStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertEquals(0, p.waitFor(), err);
        assertEquals("", err);
        assertTrue(out.startsWith("ODE refused it: "), out);
    }

    /** The child of {@link #odeFailuresPrintNoLoggingNoise}. */
    static final class Quiet {
        public static void main(String[] args) {
            World.MovableObject tiny = new World.MovableObject("c", "chip", java.util.List.of(new World.Piece(
                    new BodyShape.Cylinder(1e-9, 1e-9), Vec3.ZERO, Mat3.IDENTITY)), new Vec3(1, 0, 0.001), Mat3.IDENTITY,
                    0.01, 0.6);
            World w = new World("tiny", 0.6, 30, World.Start.ORIGIN, null, java.util.List.of(), java.util.List.of(tiny),
                    java.util.List.of(), java.util.List.of(), java.util.List.of(),
                    new World.Scoring(null, 0, java.util.List.of(), java.util.List.of(), 0, false));
            try (Simulator sim = started("snake:n=4", w)) {
                crawl(sim, 10);
                System.out.println("ran");
            } catch (RuntimeException e) {
                System.out.println("ODE refused it: " + e.getMessage());
            }
        }
    }
}
