package org.parpe.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.world.ChallengeReader;

/**
 * Issue 37, item 1's "which sensors" rule: a challenge's {@code sensors} names the sensor types a
 * script may read; a script that declares (and so may read, PARSL.md §10) another type gets a row
 * with a located error naming the rule, and a script within the rule runs.
 */
class ChallengeRulesTest {
    @TempDir
    Path dir;

    private static String snake(String sensors, String read) {
        return "<program>\n  <robot><structure><body elements=\"0..7\"/></structure>\n"
                + "    <sensors>" + sensors + "</sensors></robot>\n"
                + "  <main><race/></main>\n"
                + "  <behaviors><race><wave group=\"body\" phase=\"0.2\" period=\"1.5\"/></race></behaviors>\n"
                + "  <automata><wave states=\"up, down\"/></automata>\n"
                + "  <states><up angles=\"30 + 0 * " + read + "\" interp=\"smooth\"/><down angles=\"-30\" interp=\"smooth\"/></states>\n"
                + "</program>\n";
    }

    private Path challenge(String sensors) throws Exception {
        Path world = Path.of("../examples/worlds/race-track.xml").toAbsolutePath().normalize();
        return Files.writeString(dir.resolve("race.xml"), "<challenge world=\"" + world + "\" robot=\"snake:n=8\""
                + " duration=\"1\" max-modules=\"8\"" + sensors + "/>\n");
    }

    @Test
    void aScriptWithASensorTheChallengeDoesNotAllowHasALocatedErrorNamingTheRule() throws Exception {
        Path students = Files.createDirectories(dir.resolve("class"));
        Files.writeString(students.resolve("angles.xml"), snake("<angle elements=\"body\"/>", "$1_angle"));
        Files.writeString(students.resolve("touch.xml"), snake("\n      <touch elements=\"body\"/>",
                "$1_touch_right"));
        Path file = challenge(" sensors=\"angle\"");
        DiagnosticList found = new DiagnosticList();
        Challenge c = ChallengeReader.read(file, found);
        assertEquals(Set.of("angle"), c.sensors(), found.all().toString());
        Path out = dir.resolve("report");
        assertEquals(null, Grading.prepare(out, students, "--out"));
        List<Row> rows = new Grading(file, c, students, out, Isolation.Limits.DEFAULTS)
                .run(Students.of(students), 1, (done, total, s) -> { });
        assertEquals("angles.xml", rows.get(0).student().name());
        assertEquals(1, rows.get(0).rank(), rows.get(0).outcome().reason());
        assertEquals("touch.xml", rows.get(1).student().name());
        assertEquals("touch.xml:4:8: error: the script declares the touch sensor, which this challenge does not allow"
                + " (it allows angle; the sensors rule of the challenge)", rows.get(1).outcome().reason());
    }

    @Test
    void aChallengeAllowsEverySensorUnlessItNamesThemAndNamesOnlyKnownOnes() throws Exception {
        DiagnosticList found = new DiagnosticList();
        assertEquals(Set.of("angle", "accel", "touch", "dock"), ChallengeReader.read(challenge(""), found).sensors());
        assertEquals(Set.of(), ChallengeReader.read(challenge(" sensors=\"\""), found).sensors());
        assertTrue(found.all().isEmpty(), found.all().toString());
        assertEquals(null, ChallengeReader.read(challenge(" sensors=\"angle, sonar\""), found));
        assertEquals(List.of("race.xml:1:1: error: sensors lists sensor types (angle, accel, touch, dock), got 'sonar'"),
                found.all().stream().map(d -> d.format().replace(dir.toString() + "/", "")).toList());
    }

    /**
     * The kit rule: a challenge names the class's kit and its robot must be one the class can
     * build; a generated robot beyond the kit is refused at the challenge's element, naming the
     * rule, and one within it is read.
     */
    @Test
    void aChallengeWhoseRobotNeedsMorePartsThanTheKitIsRefusedNamingTheRule() throws Exception {
        Files.writeString(dir.resolve("kit.xml"), "<kit>\n  <part type=\"segment\" count=\"6\"/>\n</kit>\n");
        DiagnosticList found = new DiagnosticList();
        assertEquals(null, ChallengeReader.read(challenge(" kit=\"kit.xml\""), found));
        assertEquals(1, found.all().size(), found.all().toString());
        String message = found.all().get(0).format();
        assertTrue(message.startsWith(dir.resolve("race.xml") + ":1:1: error: the challenge's robot snake:n=8: "), message);
        assertTrue(message.contains("beyond the kit") && message.endsWith("(the kit rule of the challenge)"), message);

        Files.writeString(dir.resolve("kit.xml"), "<kit>\n  <part type=\"segment\" count=\"8\"/>\n</kit>\n");
        DiagnosticList fits = new DiagnosticList();
        Challenge c = ChallengeReader.read(challenge(" kit=\"kit.xml\""), fits);
        assertTrue(c != null && fits.all().isEmpty(), fits.all().toString());
    }
}
