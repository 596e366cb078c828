package org.parpe.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.internal.Docking;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;

/**
 * Docking in the simulator (PARSL.md §14, docs/simulator.md "Docking"): armed plates draw in a
 * plate they meet and latch, the latch holds the two plates together, the dock readings and the
 * d<ID>_<P> trace columns say so, a release parts them at once, and runs stay deterministic.
 */
class DockingTest {
    static final String CONFIG = Path.of("src/test/resources/docking/flat12.xml").toAbsolutePath().toString();

    /** Curls the flat snake until both ends read 2, holds, then releases the ends and opens the curl of the end modules. */
    static final String SCRIPT = """
            <program>
              <robot>
                <structure> <middle elements="1..10"/> <ends elements="0, 11"/> </structure>
                <sensors> <dock elements="ends"/> </sensors>
                <actuators> <latch elements="ends"/> </actuators>
              </robot>
              <main>
                <curlUp exit="$0_dock_0 == 2 &amp;&amp; $11_dock_1 == 2"/>
                <hold time="1"/>
                <letGo time="2"/>
              </main>
              <behaviors>
                <curlUp> <curl group="middle"/> <reach group="ends"/> </curlUp>
                <hold> <curl group="middle"/> <keep group="ends"/> </hold>
                <letGo> <curl group="middle"/> <release group="ends"/> </letGo>
              </behaviors>
              <automata>
                <curl states="bend" times="4"/>
                <reach states="grab" times="4"/>
                <keep states="held" times="1"/>
                <release states="let_go" times="1"/>
              </automata>
              <states>
                <bend angles="30"/>
                <grab angles="30" latch="0, 1"/>
                <held angles="30"/>
                <let_go angles="-30" unlatch="0, 1"/>
              </states>
            </program>
            """;

    record Outcome(String trace, Simulator sim) {
    }

    static Outcome run(String script, double seconds) throws Exception {
        LoadResult r = ScriptLoader.loadText(Path.of("curl.xml"), script, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        DiagnosticList diags = new DiagnosticList();
        Run.Builder b = Run.builder(r.program(), new RunOptions(0.01, 0, List.of()), diags);
        SimTarget target = new SimTarget(CONFIG);
        b.attach(target);
        StringWriter out = new StringWriter();
        b.trace(out).duration(seconds);
        b.build().execute();
        return new Outcome(out.toString(), target.simulator());
    }

    private static int column(String header, String name) {
        return List.of(header.split(",")).indexOf(name);
    }

    @Test
    void theEndsLatchHoldAndPartWhenReleased() throws Exception {
        Outcome o = run(SCRIPT, 20);
        String[] rows = o.trace().split("\n");
        String header = rows[0];
        assertTrue(header.endsWith(",com_x,com_y,com_z,d0_0,d0_1,d11_0,d11_1"), header);
        int d0 = column(header, "d0_0");
        int d11 = column(header, "d11_1");
        int latchedAt = -1;
        int releasedAt = -1;
        for (int i = 1; i < rows.length; i++) {
            String[] v = rows[i].split(",");
            // plates the configuration joins read 2 all the time
            assertEquals("2.000000", v[column(header, "d0_1")]);
            assertEquals("2.000000", v[column(header, "d11_0")]);
            if (latchedAt < 0 && v[d0].equals("2.000000")) {
                latchedAt = i;
                assertEquals("2.000000", v[d11], "both ends latch together, at " + v[0]);
            } else if (latchedAt > 0 && releasedAt < 0 && !v[d0].equals("2.000000")) {
                releasedAt = i;
            }
        }
        assertTrue(latchedAt > 0 && latchedAt < 1000, "the ends latch within the first 10 s of curling: row " + latchedAt);
        assertTrue(releasedAt >= latchedAt + 100, "held for the hold entry: latched at row " + latchedAt + ", parted at "
                + releasedAt);
    }

    @Test
    void aLatchHoldsThePlatesTogetherAndAReleasePartsThem() throws Exception {
        LoadResult r = ScriptLoader.loadText(Path.of("curl.xml"), SCRIPT, Map.of());
        DiagnosticList diags = new DiagnosticList();
        Run.Builder b = Run.builder(r.program(), new RunOptions(0.01, 0, List.of()), diags);
        SimTarget target = new SimTarget(CONFIG);
        b.attach(target);
        Run run = b.duration(30).build();
        double[] gapLatched = {Double.NaN};
        double[] gapAfter = {Double.NaN};
        int[] phase = {0};
        Simulator sim = target.simulator();
        run.engine().addObserver((tick, time, commanded) -> {
            double gap = gap(sim);
            if (phase[0] == 0 && sim.dock(0, 0) == Docking.LATCHED) {
                phase[0] = 1;
            } else if (phase[0] == 1) {
                gapLatched[0] = Double.isNaN(gapLatched[0]) ? gap : Math.max(gapLatched[0], gap);
                if (sim.dock(0, 0) != Docking.LATCHED) {
                    phase[0] = 2;
                    gapAfter[0] = time + 1;
                }
            } else if (phase[0] == 2 && time >= gapAfter[0]) {
                gapAfter[0] = -gap;
                phase[0] = 3;
                run.requestStop();
            }
        });
        run.execute();
        assertEquals(3, phase[0], "latched, released and a second later");
        assertTrue(gapLatched[0] < 0.003, "while latched the plate centres stay within 3 mm: " + gapLatched[0]);
        assertTrue(-gapAfter[0] > 0.02, "a second after the release the plates are more than 2 cm apart: " + -gapAfter[0]);
    }

    /** Distance between the free plate 0 of module 0 and the free plate 1 of module 11, m. */
    private static double gap(Simulator sim) {
        return gap(sim, "s11");
    }

    /** Distance between the free plate 0 of part s0 and the free plate 1 of part {@code last}, m. */
    private static double gap(Simulator sim, String last) {
        SimSnapshot s = sim.snapshot();
        return Geo.sub(plate(s, "s0", PartKind.SEGMENT_BASE, -1), plate(s, last, PartKind.SEGMENT_ARM, 1)).length();
    }

    private static Vec3 plate(SimSnapshot s, String part, PartKind kind, int side) {
        SimBody b = SimTestSupport.piece(s, part, kind);
        // a segment half is 26 mm long, centred 13 mm inside its plate
        return Geo.add(b.position(), Geo.mul(b.rotation(), new Vec3(side * 0.013, 0, 0)));
    }

    /**
     * The snake → loop → snake example (examples/docking-snake-loop.xml, issue 35): the ends latch
     * within the first curl (dock reads 2 on both), the loop rolls at least 0.5 m, and the release
     * parts the ends by more than 2 cm within 1 s.
     */
    @Test
    void theSnakeCurlsIntoALoopRollsAndLetsGo() throws Exception {
        Path example = Path.of("../examples/docking-snake-loop.xml");
        LoadResult r = ScriptLoader.load(example, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        Run.Builder b = Run.builder(r.program(), new RunOptions(0.01, 0, List.of()), new DiagnosticList());
        SimTarget target = new SimTarget("snake:n=10");
        b.attach(target);
        Run run = b.duration(25).build();
        Simulator sim = target.simulator();
        double[] latchedAt = {-1};
        double[] comAtLatch = new double[2];
        double[] rolled = {0};
        double[] releasedAt = {-1};
        double[] gapAfter = {0};
        double[] com = new double[3];
        run.engine().addObserver((tick, time, commanded) -> {
            boolean both = sim.dock(0, 0) == Docking.LATCHED && sim.dock(9, 1) == Docking.LATCHED;
            SimSnapshot s = sim.snapshot();
            com[0] = s.centerOfMass().x();
            com[1] = s.centerOfMass().y();
            if (latchedAt[0] < 0 && both) {
                latchedAt[0] = time;
                comAtLatch[0] = com[0];
                comAtLatch[1] = com[1];
            } else if (latchedAt[0] >= 0 && releasedAt[0] < 0) {
                if (both) {
                    rolled[0] = Math.max(rolled[0], Math.hypot(com[0] - comAtLatch[0], com[1] - comAtLatch[1]));
                } else {
                    releasedAt[0] = time;
                }
            } else if (releasedAt[0] >= 0 && time <= releasedAt[0] + 1) {
                gapAfter[0] = gap(sim, "s9");
            }
        });
        run.execute();
        assertTrue(latchedAt[0] > 0 && latchedAt[0] < 8, "the ends latch within the first curl: at " + latchedAt[0] + " s");
        assertTrue(rolled[0] >= 0.5, "the loop rolls at least 0.5 m: " + rolled[0]);
        assertTrue(releasedAt[0] > latchedAt[0], "the ends are released: at " + releasedAt[0]);
        assertTrue(gapAfter[0] > 0.02, "a second after the release the ends are more than 2 cm apart: " + gapAfter[0]);
        // curling up and rolling as a loop is not falling: a robot that arms a latch is judged by its hinge axis
        assertFalse(sim.metrics().fell(), sim.metrics().toJson());
    }

    @Test
    void dockingRunsAreDeterministic() throws Exception {
        assertEquals(run(SCRIPT, 8).trace(), run(SCRIPT, 8).trace());
    }

    @Test
    void aScriptWithoutPlatesKeepsItsTrace() throws Exception {
        String plain = SCRIPT.replace(" latch=\"0, 1\"", "").replace(" unlatch=\"0, 1\"", "")
                .replace("<actuators> <latch elements=\"ends\"/> </actuators>", "")
                .replace("<sensors> <dock elements=\"ends\"/> </sensors>", "")
                .replace(" exit=\"$0_dock_0 == 2 &amp;&amp; $11_dock_1 == 2\"", " time=\"5\"");
        String armed = SCRIPT.replace(" exit=\"$0_dock_0 == 2 &amp;&amp; $11_dock_1 == 2\"", " time=\"5\"");
        String a = run(plain, 3).trace();
        String b = run(armed, 3).trace();
        // up to 3 s the ends are far apart: arming changes nothing, the dock columns only add
        String[] ra = a.split("\n");
        String[] rb = b.split("\n");
        assertEquals(ra.length, rb.length);
        for (int i = 1; i < ra.length; i++) {
            assertTrue(rb[i].startsWith(ra[i] + ","), "row " + i + ": " + ra[i] + " vs " + rb[i]);
        }
    }
}
