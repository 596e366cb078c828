package org.parpe.cli.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Main;

/**
 * Issue 38: one command of each kind beyond check and run speaks German with {@code --lang de}
 * and English without it (surefire runs with {@code LC_ALL=C.UTF-8}): a simulator command
 * ({@code race}), a robot drawing ({@code robot}), a diagram ({@code diagram}), a sweep (its
 * problems come from the simulator's bundle, {@code SimMsg}), and their option help; and the
 * commands converted after them (grade, record, merge, a sweep's summary, the help of merge, grade,
 * bench, emulate, record, scan, calibrate and export).
 */
class CommandLanguagesTest {
    private static final String SCRIPT = "../examples/tutorial/03-hello-snake.xml";

    @TempDir
    Path tmp;

    private record Result(int code, String out, String err) {
    }

    private static Result parpe(String... args) {
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        int code = Main.execute(args, new PrintStream(o, true, StandardCharsets.UTF_8),
                new PrintStream(e, true, StandardCharsets.UTF_8), Map.<String, String>of()::get);
        return new Result(code, o.toString(StandardCharsets.UTF_8), e.toString(StandardCharsets.UTF_8));
    }

    private static Result german(String... args) {
        List<String> all = new ArrayList<>(List.of(args));
        all.addAll(List.of("--lang", "de"));
        return parpe(all.toArray(String[]::new));
    }

    @Test
    void raceSpeaksTheChosenLanguage() {
        Result en = parpe("race", SCRIPT, "--duration", "-1");
        Result de = german("race", SCRIPT, "--duration", "-1");
        assertEquals(2, en.code());
        assertEquals("parpe: --duration must be > 0 seconds, got -1.0\n", en.err());
        assertEquals(2, de.code());
        assertEquals("parpe: --duration muss > 0 Sekunden sein, ist aber -1.0\n", de.err());
    }

    @Test
    void robotAndDiagramSpeakTheChosenLanguage() {
        String svg = tmp.resolve("snake.svg").toString();
        assertEquals("wrote " + svg + "\n", parpe("robot", "snake:n=4", "--out", svg).out());
        assertEquals(svg + " geschrieben\n", german("robot", "snake:n=4", "--out", svg).out());

        String[] wide = {"diagram", SCRIPT, "--out", svg, "--width", "100"};
        assertEquals("parpe: --width is for a .png file; an SVG scales to any size by itself\n", parpe(wide).err());
        assertEquals("parpe: --width gilt für eine .png-Datei; ein SVG lässt sich von selbst auf jede Größe bringen\n",
                german(wide).err());
    }

    @Test
    void aSweepExplainsItsProblemInTheChosenLanguage() {
        String[] args = {"sweep", "../examples/tutorial/07-parameters-snake.xml", "--vary", "amp=40..20", "--out",
                tmp.resolve("s.csv").toString()};
        Result en = parpe(args);
        Result de = german(args);
        assertEquals(2, en.code(), en.err());
        assertTrue(en.err().contains("--vary amp=40..20: empty range: the start 40 is greater than the end 20"), en.err());
        assertTrue(de.err().contains("--vary amp=40..20: leerer Bereich: der Anfang 40 ist größer als das Ende 20"), de.err());
    }

    @Test
    void aSweepsOptionErrorIsInTheChosenLanguage() {
        String[] args = {"sweep", "../examples/tutorial/07-parameters-snake.xml", "--vary", "amp=0..10", "--jobs", "0",
            "--out", tmp.resolve("s.csv").toString()};
        Result en = parpe(args);
        Result de = german(args);
        assertTrue(en.err().contains("parpe: --jobs must be within [1, 1024], got 0\n"), en.err());
        assertTrue(de.err().contains("parpe: --jobs muss in [1, 1024] liegen, ist aber 0\n"), de.err());
    }

    @Test
    void theHelpOfRaceRobotDiagramSweepAndOptimizeIsTranslated() {
        assertHelp(parpe("race", "--help"), "PARSL scripts to race.");
        assertHelp(german("race", "--help"), "PARSL-Skripte, die gegeneinander antreten.");
        assertHelp(german("robot", "--help"), "Den Roboter zeichnen: DATEI.svg oder DATEI.png.");
        assertHelp(german("diagram", "--help"), "program, lanes, ring, phase oder gait (Vorgabe: program).");
        assertHelp(german("sweep", "--help"), "Simulierte Sekunden je Lauf (Vorgabe 20).");
        assertHelp(german("optimize", "--help"), "Höchstens so viele Simulationen (Vorgabe 500).");
    }

    /**
     * {@code grade} with a broken challenge: the challenge's errors keep their
     * {@code FILE:LINE:COL: error:} places in German (only the text after them differs), and
     * grade's own line after them is German.
     */
    @Test
    void gradeKeepsThePlacesOfAChallengesErrorsInGerman() throws IOException {
        Path challenge = tmp.resolve("challenge.xml");
        Files.writeString(challenge, "<challenge>\n  <world>\n</challenge>\n");
        Files.createDirectories(tmp.resolve("students"));
        String[] args = {"grade", challenge.toString(), tmp.resolve("students").toString(), "--out", tmp.resolve("report").toString()};
        Result en = parpe(args);
        Result de = german(args);
        assertEquals(2, en.code(), en.err());
        assertEquals(2, de.code(), de.err());
        assertTrue(en.err().endsWith("parpe: the challenge '" + challenge + "' has errors (above)\n"), en.err());
        assertTrue(de.err().endsWith("parpe: die Aufgabe '" + challenge + "' hat Fehler (oben)\n"), de.err());
        assertSamePlacesOtherWords(en.err(), de.err());
    }

    /** {@code record} from a broken script: its errors at the same places, the line before them German. */
    @Test
    void recordKeepsThePlacesOfAScriptsErrorsInGerman() throws IOException {
        Path script = tmp.resolve("broken.xml");
        Files.writeString(script, "<program>\n  <robot>\n</program>\n");
        String[] args = {"record", "--script", script.toString(), "--group", "body", "--port", tmp.resolve("tty").toString(),
            "--out", tmp.resolve("rec.xml").toString()};
        Result en = parpe(args);
        Result de = german(args);
        assertEquals(2, en.code(), en.err());
        assertTrue(en.err().startsWith("parpe: the script has errors:\n" + script + ":"), en.err());
        assertTrue(de.err().startsWith("parpe: das Skript hat Fehler:\n" + script + ":"), de.err());
        assertSamePlacesOtherWords(en.err(), de.err());
    }

    @Test
    void mergeRefusesAFileGivenTwiceInTheChosenLanguage() throws IOException {
        Path shard = Files.writeString(tmp.resolve("a.csv"), "run,amp\n");
        String[] args = {"merge", shard.toString(), shard.toString()};
        assertEquals("parpe: '" + shard + "' is given twice\n", parpe(args).err());
        assertEquals("parpe: '" + shard + "' ist zweimal angegeben\n", german(args).err());
        assertEquals("parpe: 「" + shard + "」が 2 回指定されています\n", parpe(withLang(args, "ja")).err());
    }

    /** A sweep's summary, read by researchers, in German; English as it always was. */
    @Test
    void aSweepsSummaryIsInTheChosenLanguage() {
        String[] args = {"sweep", "../examples/tutorial/07-parameters-snake.xml", "--vary", "amp=10,20", "--duration", "0.5",
            "--jobs", "1", "--out", tmp.resolve("s.csv").toString()};
        Result en = parpe(args);
        Result de = german(args);
        assertEquals(0, en.code(), en.err());
        assertTrue(en.err().contains("parpe: 2 of 2 runs; 0 with errors, 0 fell over\n"), en.err());
        assertTrue(en.err().contains("parpe: plot in "), en.err());
        assertTrue(de.err().contains("parpe: 2 von 2 Läufen; 0 mit Fehlern, 0 umgefallen\n"), de.err());
        assertTrue(de.err().contains("parpe: Diagramm in "), de.err());
    }

    @Test
    void theHelpOfMergeGradeBenchAndTheHardwareCommandsIsTranslated() {
        assertHelp(german("merge", "--help"), "Die Dateien der Teile, in beliebiger Reihenfolge.");
        assertHelp(german("grade", "--help"), "Speicher (Heap) eines Laufs (Vorgabe 512).");
        assertHelp(german("bench", "--help"), "Die Benchmarks auflisten und beenden.");
        assertHelp(german("emulate", "--help"), "Die serielle Schnittstelle, an der nachgebildet wird");
        assertHelp(german("record", "--help"), "Nach N Posen aufhören.");
        assertHelp(german("scan", "--help"), "Eine vorhandene --out-Datei ersetzen.");
        assertHelp(german("calibrate", "--help"), "Das Hardware-Profil, dessen Nullpunkte gesetzt werden.");
        assertHelp(german("export", "--help"), "Der Ordner, in den die Dateien geschrieben werden (wird angelegt, wenn es ihn nicht gibt).");
        assertHelp(parpe(withLang(new String[] {"scan", "--help"}, "es")), "Reemplazar un archivo --out que ya existe.");
        assertHelp(parpe(withLang(new String[] {"record", "--help"}, "ja")), "N 個のポーズで止めます。");
    }

    /**
     * The two outputs have the same {@code FILE:LINE:COL: error: } lines at the same places,
     * each with a text of its own after them.
     */
    private static void assertSamePlacesOtherWords(String english, String translated) {
        Pattern placed = Pattern.compile("(?m)^(\\S+:\\d+:\\d+: error: )(.*)$");
        Matcher e = placed.matcher(english);
        Matcher t = placed.matcher(translated);
        int n = 0;
        while (e.find()) {
            assertTrue(t.find(), "no located error in\n" + translated);
            assertEquals(e.group(1), t.group(1));
            assertNotEquals(e.group(2), t.group(2), "not translated: " + t.group(2));
            n++;
        }
        assertFalse(t.find(), translated);
        assertTrue(n > 0, "no located error in\n" + english);
    }

    private static String[] withLang(String[] args, String code) {
        List<String> all = new ArrayList<>(List.of(args));
        all.addAll(List.of("--lang", code));
        return all.toArray(String[]::new);
    }

    /** {@code text} in the help printed (picocli wraps it at 80 columns: compared without the line breaks). */
    private static void assertHelp(Result help, String text) {
        String shown = (help.out() + help.err()).replaceAll("\\s+", " ");
        assertTrue(shown.contains(text), "no '" + text + "' in\n" + help.out() + help.err());
    }
}
