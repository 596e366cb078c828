package org.parpe.gui.automation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.ResourceBundle;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.BundleCheck;
import org.parpe.core.text.Lang;
import org.parpe.gui.Main;

/**
 * Issue 38: {@code parpe gui}'s own options speak the user's language as every command's do
 * ({@code parpe check --help --lang de}): its help from the bundle {@link LaunchOptions#HELP}, its
 * parse errors by the command line's {@code ParseErrors}. Before, both were English whatever
 * {@code --lang} said. No display is needed: the options are read before the IDE opens.
 */
class LaunchLanguageTest {

    private record Result(int code, String out, String err) {
    }

    /** {@code parpe gui ARGS}, the language it leaves behind put back. */
    private static Result gui(String... args) {
        PrintStream out = System.out;
        PrintStream err = System.err;
        Locale before = Lang.current();
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            List<String> all = new ArrayList<>(List.of("gui"));
            all.addAll(List.of(args));
            int code = Main.run(all.toArray(String[]::new));
            return new Result(code, o.toString(StandardCharsets.UTF_8), e.toString(StandardCharsets.UTF_8));
        } finally {
            System.setOut(out);
            System.setErr(err);
            Lang.use(before);
        }
    }

    @Test
    void helpIsInTheChosenLanguage() {
        Result de = gui("--help", "--lang", "de");
        assertEquals(0, de.code(), de.toString());
        assertTrue(de.out().startsWith("Aufruf: parpe gui "), de.out());
        assertTrue(de.out().contains("Die PARPE-IDE öffnen, auf Wunsch mit einem Skript;"), de.out());
        assertTrue(de.out().matches("(?s).*\n +--run-for=S +das Skript im Simulator S Sekunden simulierter.*"),
                de.out());
        assertTrue(de.out().matches("(?s).*-h, --help +diese Hilfe zeigen und beenden\n.*"), de.out());
        assertFalse(de.out().contains("seconds of simulated time"), de.out());
        assertTrue(gui("--help", "--lang", "es").out().startsWith("Uso: parpe gui "));
        assertTrue(gui("--lang=ja", "-h").out().startsWith("使い方: parpe gui "));
    }

    @Test
    void englishHelpIsPicocliAsBefore() {
        Result en = gui("--help", "--lang", "en");
        assertEquals(0, en.code());
        assertTrue(en.out().startsWith("Usage: parpe gui "), en.out());
        assertTrue(en.out().matches("(?s).*\n +--run-for=S +run the script in the simulator for S seconds of\n +simulated time\n.*"),
                en.out());
    }

    /** The first line of standard error, exit code 2, and the usage after it in the same language. */
    private static String error(Result r, String usage) {
        assertEquals(2, r.code(), r.toString());
        assertTrue(r.err().contains("\n" + usage + "parpe gui "), r.err());
        return r.err().lines().findFirst().orElse("");
    }

    @Test
    void parseErrorsAreInTheChosenLanguage() {
        assertEquals("parpe gui: error: unbekannte Option: '--bogus'", error(gui("--bogus", "--lang", "de"), "Aufruf: "));
        assertEquals("parpe gui: error: der Wert für die Option '--run-for' (S) fehlt",
                error(gui("--lang", "de", "--run-for"), "Aufruf: "));
        assertEquals("parpe gui: error: --run-for muss eine Zahl von Sekunden >= 0 sein, angegeben ist 'bald'",
                error(gui("--run-for", "bald", "--lang=de"), "Aufruf: "));
        assertEquals("parpe gui: error: nur eine DATEI darf angegeben werden, angegeben sind 'a.xml' und 'b.xml'",
                error(gui("a.xml", "b.xml", "--lang", "de"), "Aufruf: "));
        assertEquals("parpe gui: error: opción desconocida: '--bogus'", error(gui("--bogus", "--lang", "es"), "Uso: "));
    }

    @Test
    void englishErrorsArePicocliAsBefore() {
        assertEquals("parpe gui: error: Unknown option: '--bogus'", error(gui("--bogus", "--lang", "en"), "Usage: "));
        assertEquals("parpe gui: error: Missing required parameter for option '--run-for' (S)",
                error(gui("--lang", "en", "--run-for"), "Usage: "));
    }

    /**
     * The translators' check of the gui's help (as {@code CliTextTest} does the command line's):
     * each language has a text for the synopsis heading, the description and every option and
     * parameter, and no key that names none of them.
     */
    @Test
    void everyHelpBundleHasExactlyTheKeysOfTheOptions() {
        Set<String> keys = new TreeSet<>(LaunchOptions.helpKeys());
        assertTrue(keys.containsAll(List.of("usage.synopsisHeading", "usage.description", "files", "run-for", "lang", "help")),
                keys.toString());
        List<String> problems = new ArrayList<>();
        for (Locale l : Lang.SUPPORTED.subList(1, Lang.SUPPORTED.size())) {
            ResourceBundle b = BundleCheck.own(LaunchOptions.HELP, l);
            assertNotNull(b, "no help bundle for " + l);
            Set<String> have = new TreeSet<>(Collections.list(b.getKeys()));
            keys.stream().filter(k -> !have.contains(k)).forEach(k -> problems.add(l + ": missing " + k));
            have.stream().filter(k -> !keys.contains(k)).forEach(k -> problems.add(l + ": unused " + k));
        }
        assertEquals(List.of(), problems, String.join("\n", problems));
    }

}
