package org.parpe.cli.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Main;

/**
 * Issue 38: one command of each kind beyond check and run speaks German with {@code --lang de}
 * and English without it (surefire runs with {@code LC_ALL=C.UTF-8}): a simulator command
 * ({@code race}), a robot drawing ({@code robot}), a diagram ({@code diagram}), a sweep (its
 * problems come from the simulator's bundle, {@code SimMsg}), and their option help.
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

    /** {@code text} in the help printed (picocli wraps it at 80 columns: compared without the line breaks). */
    private static void assertHelp(Result help, String text) {
        String shown = (help.out() + help.err()).replaceAll("\\s+", " ");
        assertTrue(shown.contains(text), "no '" + text + "' in\n" + help.out() + help.err());
    }
}
