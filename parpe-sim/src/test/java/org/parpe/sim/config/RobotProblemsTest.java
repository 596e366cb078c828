package org.parpe.sim.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.sim.internal.Assembly;

/**
 * Issue 33's bad configurations, case by case: each gets a located message from reading and
 * assembling the robot (what {@code parpe robot --check} and a run both do), never an exception
 * or a hang.
 */
class RobotProblemsTest {
    @TempDir
    Path dir;

    private List<Diagnostic> errors(String name, String text) throws IOException {
        return BadConfigs.runErrors(BadConfigs.write(dir, name, text));
    }

    @Test
    void overlappingPartsAreReportedAtTheLaterPart() throws IOException {
        List<Diagnostic> e = errors("overlap.xml", BadConfigs.OVERLAP);
        assertEquals(1, e.size(), e.toString());
        assertTrue(e.get(0).toString().startsWith(dir.resolve("overlap.xml") + ":6:3: error: part 'd' overlaps part"
                + " 'body' (line 2) by "), e.toString());
    }

    @Test
    void noStandardRobotOverlaps() {
        for (String spec : List.of("snake:n=30", "snake:n=12,axes=alternate", "loop", "loop:n=12", "wheel", "wheel:n=3",
                "wheel:n=16", "centipede", "humanoid", "../examples/configs/tee-snake.xml",
                "../examples/configs/wheel6.xml")) {
            DiagnosticList d = new DiagnosticList();
            RobotConfig c = RobotConfigs.resolve(spec, new int[0], d);
            assertNotNull(Assembly.build(c, d), spec + ": " + d.all());
        }
    }

    /**
     * Issue 33 item 6: the Fig. 2 humanoid of examples/configs is the humanoid generator's robot:
     * the same parts and every piece in the same place (1e-9 m) and the same hinges.
     */
    @Test
    void theHumanoidFileIsTheGeneratorsHumanoid() {
        DiagnosticList d = new DiagnosticList();
        Assembly file = Assembly.build(RobotConfigs.resolve("../examples/configs/humanoid15.xml", new int[0], d), d);
        Assembly gen = Assembly.build(RobotConfigs.resolve("humanoid", new int[0], d), d);
        assertTrue(d.all().isEmpty(), d.all().toString());
        assertEquals(gen.pieces().size(), file.pieces().size());
        for (int i = 0; i < gen.pieces().size(); i++) {
            Assembly.PlacedPiece a = gen.pieces().get(i);
            Assembly.PlacedPiece b = file.pieces().get(i);
            assertEquals(a.part().name(), b.part().name());
            assertEquals(a.part().moduleId(), b.part().moduleId());
            assertTrue(org.parpe.sim.geom.Geo.sub(a.position(), b.position()).length() < 1e-9, a + " vs " + b);
            assertTrue(org.parpe.sim.geom.Geo.angleBetween(a.rotation(), b.rotation()) < 1e-9, a + " vs " + b);
        }
        assertEquals(gen.hinges().size(), file.hinges().size());
    }

    @Test
    void aPlateUsedTwiceNamesTheFirstConnection() throws IOException {
        List<Diagnostic> e = errors("twice.xml", BadConfigs.PLATE_TWICE);
        assertEquals(dir.resolve("twice.xml") + ":6:3: error: plate 1 of part 'a' is already connected (line 5);"
                + " a plate takes one connection", e.get(0).toString(), e.toString());
    }

    @Test
    void aLoopThatDoesNotCloseSaysHowFarApartThePlatesAre() throws IOException {
        List<Diagnostic> e = errors("open.xml", BadConfigs.OPEN_LOOP);
        assertEquals(1, e.size(), e.toString());
        assertTrue(e.get(0).toString().matches("(?s).*open\\.xml:[89]:3: error: connection [a-d]\\.1 -> [a-d]\\.0 closes a loop but"
                + " does not fit: the plates are [0-9.]+ mm and 10\\.0 degrees apart.*"), e.toString());
    }

    @Test
    void anUnknownPartTypeSuggestsTheKnownOnes() throws IOException {
        List<Diagnostic> e = errors("type.xml", BadConfigs.UNKNOWN_TYPE);
        assertEquals(dir.resolve("type.xml") + ":2:3: error: unknown part type 'wheel'; expected segment, node, foot or hub",
                e.get(0).toString());
    }

    @Test
    void tenThousandPartsAreCheckedWithoutHanging() throws IOException {
        // a bound against a hang (placement looked through every connection for every part,
        // overlaps compared every pair), not a timing
        List<Diagnostic> straight = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> check(chain(false)));
        assertTrue(straight.isEmpty(), straight.toString());
        // every other segment bent 90 degrees the same way folds the chain onto itself all along
        Path folded = chain(true);
        List<Diagnostic> e = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> check(folded));
        assertEquals(21, e.size(), "the first 20 overlaps and a note that there are more");
        assertEquals(folded + ":10:3: error: part 's8' overlaps part 's0' (line 2) by 26.0 mm at the initial pose"
                + " (at most 4 mm); change an initial angle or where it is connected", e.get(0).toString());
        assertTrue(e.get(20).message().startsWith("more parts overlap; these are the first 20"), e.get(20).toString());
    }

    private static List<Diagnostic> check(Path f) {
        DiagnosticList d = new DiagnosticList();
        Assembly.build(RobotConfigs.resolve(f.toString(), new int[0], d), d);
        return d.all();
    }

    /** A chain of 10 000 segments, every other one bent 90 degrees if {@code folded}. */
    private Path chain(boolean folded) throws IOException {
        return BadConfigs.write(dir, folded ? "folded.xml" : "straight.xml", BadConfigs.chain(folded));
    }

    @Test
    void aBinaryFileIsNotWellFormedXmlAtItsStart() throws IOException {
        Path f = Files.write(dir.resolve("noise.xml"), BadConfigs.noise());
        List<Diagnostic> e = BadConfigs.runErrors(f);
        assertEquals(1, e.size(), e.toString());
        assertTrue(e.get(0).toString().startsWith(f + ":1:"), e.toString());
        assertTrue(e.get(0).message().startsWith("not well-formed XML"), e.toString());
    }

    @Test
    void externalEntitiesAreRefusedWithTheirDoctype() throws IOException {
        Path secret = dir.resolve("secret.txt");
        Files.writeString(secret, "s3cr3t");
        List<Diagnostic> e = errors("xxe.xml", BadConfigs.externalEntity(secret));
        assertEquals(1, e.size(), e.toString());
        assertTrue(e.get(0).toString().startsWith(dir.resolve("xxe.xml") + ":2:"), e.toString());
        assertTrue(e.get(0).message().startsWith("DOCTYPE declarations are not allowed in a robot configuration"),
                e.toString());
        assertTrue(!e.toString().contains("s3cr3t"), e.toString());
    }
}
