package org.parpe.sim.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.text.Lang;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;
import org.parpe.sim.bridge.Export;
import org.parpe.sim.config.PartType;
import org.parpe.sim.build.RobotDraft;
import org.parpe.sim.grade.ReportPage;
import org.parpe.sim.sweep.IncompleteSweepException;
import org.parpe.sim.sweep.SweepCsv;
import org.parpe.sim.sweep.SweepException;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;
import org.parpe.sim.world.WorldScore;

/**
 * The simulator's messages in the user's language (issue 38: "error and warning messages of ...
 * the simulator ... and the export" come from the bundles): before, a robot that does not fit its
 * world, a score in words and a refused export folder were English whatever the language; so were
 * the robot builder's refusals and edit names, the shard merger's problems and the grading report.
 */
class SimMessagesLanguageTest {
    @TempDir
    Path dir;

    @AfterEach
    void english() {
        Lang.use(Locale.ENGLISH);
    }

    @Test
    void aRobotThatDoesNotFitItsWorldIsAWarningInGerman() throws Exception {
        Path w = Files.writeString(dir.resolve("wall.xml"), """
                <world>
                  <wall x0="-1" y0="0" x1="1" y1="0" height="0.2" thickness="0.2"/>
                </world>
                """);
        DiagnosticList d = new DiagnosticList();
        World world = WorldReader.read(w, d);
        assertNotNull(world, d.all().toString());
        Lang.use(Locale.GERMAN);
        try (Simulator s = SimTarget.create("snake:n=4", new int[] {0, 1, 2, 3}, d, world)) {
            List<String> warnings = d.all().stream().map(x -> x.format()).toList();
            assertTrue(warnings.stream().anyMatch(m -> m.startsWith("simulated robot snake:n=4: warning: der Roboter passt nicht"
                    + " in die Welt wall.xml: er beginnt ") && m.endsWith(" mm tief in ihren Wänden, Rampen, Trümmern oder"
                    + " Gegenständen; wähle einen Roboter, der passt, oder eine Welt, die für ihn gemacht ist")), warnings.toString());
        }
    }

    /** The parts of a score as WorldScore's documentation shows them, and the same in German. */
    @Test
    void aScoreInWordsInEnglishAndGerman() {
        WorldScore s = new WorldScore(10, 31.2, 1.4, 2, 1, 2, "tilt");
        assertEquals("zone 31.2 s, path 1.40 m, 2 checkpoints, 1 delivered, 2 presses, disqualified (tilt)", s.inWords());
        Lang.use(Locale.GERMAN);
        assertEquals("Zielzone 31.2 s, Weg 1.40 m, 2 Kontrollpunkte, 1 abgeliefert, 2 Hebeldrücke, disqualifiziert (gekippt)",
                s.inWords());
        assertEquals("1 Kontrollpunkt, 1 Hebeldruck, disqualifiziert (Arena verlassen)",
                new WorldScore(0, Double.NaN, 0, 1, 0, 1, "arena").inWords());
    }

    /**
     * Part counts inside kit messages and the robot's summary: English plurals of the file's
     * words ("3 segments") stood in every language, as in "der Roboter braucht 3 segments".
     */
    @Test
    void partCountsInEnglishAndGerman() {
        assertEquals("1 segment, 12 segments, 1 foot, 2 feet, 0 hubs", String.join(", ",
                PartType.SEGMENT.count(1).toString(), PartType.SEGMENT.count(12).toString(),
                PartType.FOOT.count(1).toString(), PartType.FOOT.count(2).toString(), PartType.HUB.count(0).toString()));
        Lang.use(Locale.GERMAN);
        assertEquals("1 Segment, 12 Segmente, 1 Fuß, 2 Füße, 0 Naben, 3 Knoten", String.join(", ",
                PartType.SEGMENT.count(1).toString(), PartType.SEGMENT.count(12).toString(),
                PartType.FOOT.count(1).toString(), PartType.FOOT.count(2).toString(), PartType.HUB.count(0).toString(),
                PartType.NODE.count(3).toString()));
        assertEquals("vom Typ Nabe ist im Bausatz nichts mehr übrig (er hat 2 Naben)",
                SimMsg.BUILD_KIT_EMPTY.text(PartType.HUB.noun(), PartType.HUB.count(2)));
        Lang.use(Locale.forLanguageTag("ja"));
        assertEquals("セグメント 1 個, 足 4 個", PartType.SEGMENT.count(1) + ", " + PartType.FOOT.count(4));
    }

    @Test
    void anExportIntoAFileIsRefusedInGerman() throws IOException {
        Path file = Files.writeString(dir.resolve("out"), "x");
        assertEquals("'" + file + "' is a file, not a folder", Export.refusal(file, List.of("snake.xml")));
        Lang.use(Locale.GERMAN);
        assertEquals("'" + file + "' ist eine Datei, kein Ordner", Export.refusal(file, List.of("snake.xml")));
    }

    private static final String TWO = String.join("\n", "<robot-config>", "  <part name=\"a\" type=\"segment\" id=\"0\"/>",
            "  <part name=\"b\" type=\"segment\" id=\"1\"/>", "  <connect from=\"a.1\" to=\"b.0\"/>", "</robot-config>", "");

    @Test
    void theBuildersRefusalsAndEditNamesInGerman() {
        RobotDraft d = RobotDraft.of("two.xml", TWO);
        assertEquals("there is no part 'zz'", d.remove("zz").refusal());
        assertEquals("Remove b", d.remove("b").description());
        Lang.use(Locale.GERMAN);
        assertEquals("es gibt kein Teil 'zz'", d.remove("zz").refusal());
        assertEquals("b entfernen", d.remove("b").description());
        assertEquals("'a' ist die Wurzel und 1 Teil hängt daran; mache zuerst ein anderes Teil zur Wurzel",
                d.remove("a").refusal());
    }

    @Test
    void theMergersProblemsInGermanKeepTheirPlaceAndErrorWord() {
        Map<String, List<String>> notASweep = Map.of("a.csv", List.of("x,y"));
        SweepException e = assertThrows(SweepException.class, () -> SweepCsv.merge(notASweep));
        assertEquals("a.csv:1: error: not a sweep result (its first line must be the header 'run,runs,...' that parpe sweep"
                + " writes)", e.getMessage());
        Map<String, List<String>> unfinished = Map.of("s1.csv", List.of(SweepCsv.shardStart(1, 2, 0, 2, 4), "run,runs,x"));
        Lang.use(Locale.GERMAN);
        assertEquals("a.csv:1: error: kein Sweep-Ergebnis (seine erste Zeile muss die Kopfzeile 'run,runs,...' sein, die"
                + " parpe sweep schreibt)", e.getMessage(), "the message is put in words when it is shown");
        IncompleteSweepException i = assertThrows(IncompleteSweepException.class, () -> SweepCsv.merge(unfinished));
        assertEquals("s1.csv: error: Teil 1/2 ist unfertig: es enthält 0 seiner 2 Läufe (Läufe 0..1); seine Aufgabe wurde"
                + " vor dem Ende angehalten oder beendet\nerror: Teil 2/2 fehlt (Läufe 2..3)", i.getMessage());
    }

    @Test
    void theGradingReportsWordsInGerman() {
        Path worldFile = Path.of("../examples/worlds/race-track.xml").toAbsolutePath().normalize();
        DiagnosticList d = new DiagnosticList();
        World world = WorldReader.read(worldFile, d);
        assertNotNull(world, d.all().toString());
        Challenge c = new Challenge(Path.of("race.xml"), worldFile, "snake:n=8", 2, 0.01, Map.of(), 8, Set.of(),
                Challenge.TieBreak.DISTANCE);
        String english = ReportPage.html(List.of(), c, world);
        assertTrue(english.contains("<html lang=\"en\">") && english.contains("<h1>Results: race.xml</h1>")
                && english.contains("<th>rank</th><th>student</th>"), english);
        Lang.use(Locale.GERMAN);
        String german = ReportPage.html(List.of(), c, world);
        assertTrue(german.contains("<html lang=\"de\">") && german.contains("<title>Ergebnisse: race.xml</title>")
                && german.contains("<p>0 Schülerinnen und Schüler: 0 mit Rang, 0 mit Problemen (Aufgabe race.xml, snake:n=8, 2 s)")
                && german.contains("<th>Rang</th><th>Schüler</th><th>Punktzahl</th>"), german);
    }
}
