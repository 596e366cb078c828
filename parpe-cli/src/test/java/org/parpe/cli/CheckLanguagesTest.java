package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * {@code parpe check} of a script with the mistakes students make most prints the same located
 * errors in English, German, Spanish and Japanese: the same FILE:LINE:COL, the same words
 * {@code error}/{@code warning} (tools parse them), the same count and order; only the message
 * after them differs (issue 38, acceptance). And how the language is chosen: {@code --lang} over
 * {@code LC_ALL} over {@code LC_MESSAGES} over {@code LANG}.
 */
class CheckLanguagesTest {
    private static final Pattern LOCATED = Pattern.compile("(?m)^(\\S+:\\d+:\\d+): (error|warning): (.*)$");

    private record Result(int code, String out, String err) {
    }

    private static Result parpe(Map<String, String> env, String... args) {
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        int code = Main.execute(args, new PrintStream(o, true, StandardCharsets.UTF_8),
                new PrintStream(e, true, StandardCharsets.UTF_8), env::get);
        return new Result(code, o.toString(StandardCharsets.UTF_8), e.toString(StandardCharsets.UTF_8));
    }

    private static String mistakes() throws URISyntaxException {
        return Path.of(CheckLanguagesTest.class.getResource("/mistakes/hello-snake-mistakes.xml").toURI()).toString();
    }

    /** The places and severities of the located lines, and their messages. */
    private static List<String[]> located(String err) {
        List<String[]> out = new ArrayList<>();
        Matcher m = LOCATED.matcher(err);
        while (m.find()) {
            out.add(new String[] {m.group(1) + ": " + m.group(2), m.group(3)});
        }
        return out;
    }

    @Test
    void sameLocatedErrorsInEveryLanguageOnlyTheMessageDiffers() throws Exception {
        String file = mistakes();
        Result en = parpe(Map.of(), "check", file, "--lang", "en");
        assertEquals(1, en.code(), en.err());
        List<String[]> english = located(en.err());
        assertEquals(6, english.size(), en.err());
        assertTrue(en.err().contains(":24:23: error: state 'donw' is not defined in <states>"), en.err());
        for (String lang : List.of("de", "es", "ja")) {
            Result r = parpe(Map.of(), "check", file, "--lang", lang);
            assertEquals(1, r.code(), lang + ": " + r.err());
            List<String[]> found = located(r.err());
            assertEquals(english.size(), found.size(), lang + ": " + r.err());
            for (int i = 0; i < english.size(); i++) {
                assertEquals(english.get(i)[0], found.get(i)[0], lang + ": the place and severity of line " + i);
                assertNotEquals(english.get(i)[1], found.get(i)[1], lang + ": the message of line " + i + " is English");
            }
            assertTrue(r.err().trim().endsWith(": " + Map.of("de", "6 Fehler", "es", "6 errores", "ja", "エラー 6 件").get(lang)),
                    r.err());
        }
    }

    @Test
    void theEnvironmentChoosesTheLanguageAndLangOverridesIt() throws Exception {
        String file = mistakes();
        String german = "Zustand 'donw' ist nicht in <states> definiert";
        assertTrue(parpe(Map.of("LANG", "de_DE.UTF-8"), "check", file).err().contains(german));
        assertTrue(parpe(Map.of("LC_MESSAGES", "de_DE.UTF-8", "LANG", "ja_JP.UTF-8"), "check", file).err().contains(german));
        assertTrue(parpe(Map.of("LC_ALL", "es_ES.UTF-8", "LC_MESSAGES", "de_DE.UTF-8"), "check", file).err()
                .contains("el estado 'donw' no está definido en <states>"));
        // LC_ALL=C wins over a German LANG: English, as the tests and the conformance runner want
        assertTrue(parpe(Map.of("LC_ALL", "C", "LANG", "de_DE.UTF-8"), "check", file).err()
                .contains("state 'donw' is not defined"));
        // --lang en gives the English text for a bug report, --lang=ja the Japanese one
        assertTrue(parpe(Map.of("LANG", "de_DE.UTF-8"), "check", file, "--lang", "en").err().contains("state 'donw'"));
        assertTrue(parpe(Map.of("LANG", "de_DE.UTF-8"), "--lang=ja", "check", file).err().contains("状態「donw」"));
    }

    /** {@code --lang qps}, the testers' pseudo-language (docs/decisions.md): same places, English messages accented. */
    @Test
    void thePseudoLanguageKeepsThePlacesAndShowsEveryMessageBracketed() throws Exception {
        String file = mistakes();
        List<String[]> english = located(parpe(Map.of(), "check", file, "--lang", "en").err());
        Result qps = parpe(Map.of(), "check", file, "--lang", "qps");
        assertEquals(1, qps.code(), qps.err());
        List<String[]> found = located(qps.err());
        assertEquals(english.size(), found.size(), qps.err());
        for (int i = 0; i < found.size(); i++) {
            assertEquals(english.get(i)[0], found.get(i)[0], "the place and severity of line " + i);
            assertTrue(found.get(i)[1].startsWith("[") && found.get(i)[1].endsWith("]"), found.get(i)[1]);
        }
        assertTrue(qps.err().contains("štåté 'donw' îš ñöt đéfîñéđ"), qps.err());
        // picocli's help has no pseudo file: English, and no failure
        Result help = parpe(Map.of(), "check", "--help", "--lang", "qps");
        assertEquals(0, help.code(), help.err());
        assertTrue(help.out().startsWith("Usage: parpe check"), help.out());
    }

    @Test
    void anUnknownLanguageIsAUsageErrorInTheEnvironmentsLanguage() {
        Result r = parpe(Map.of("LANG", "de_DE.UTF-8"), "check", "x.xml", "--lang", "fr");
        assertEquals(2, r.code());
        assertEquals("parpe: unbekannte Sprache 'fr'; die Sprachen sind en, de, es, ja", r.err().trim());
        assertEquals(2, parpe(Map.of(), "check", "x.xml", "--lang").code());
    }

    @Test
    void helpIsInTheChosenLanguage() {
        Result de = parpe(Map.of(), "check", "--help", "--lang", "de");
        assertEquals(0, de.code(), de.err());
        assertTrue(de.out().startsWith("Aufruf: parpe check"), de.out());
        assertTrue(de.out().contains("PARSL-Skripte oder Ordner davon, die geprüft werden."), de.out());
        Result ja = parpe(Map.of("LANG", "ja_JP.UTF-8"), "--help");
        assertTrue(ja.out().contains("コマンド:"), ja.out());
        assertTrue(ja.out().contains("PARSL スクリプトを検査します"), ja.out());
        Result es = parpe(Map.of(), "run", "--help", "--lang", "es");
        assertTrue(es.out().contains("Tic del planificador (por defecto 0.01)."), es.out());
        // English stays as it was
        Result en = parpe(Map.of(), "check", "--help");
        assertTrue(en.out().startsWith("Usage: parpe check"), en.out());
        assertTrue(en.out().contains("PARSL scripts, or folders of them, to check."), en.out());
    }

    @Test
    void theCommandLinesOwnMessagesAreTranslated() throws Exception {
        Result r = parpe(Map.of(), "run", mistakes(), "--tick", "100", "--lang", "es");
        assertEquals(2, r.code(), r.err());
        assertEquals("parpe: --tick debe estar en [0.000001, 10] segundos, pero es 100.0", r.err().trim());
        Result ok = parpe(Map.of(), "check", Path.of("../examples/hello-snake.xml").toString(), "--lang", "ja");
        assertEquals(0, ok.code(), ok.err());
        assertEquals("../examples/hello-snake.xml: OK", ok.out().trim());
    }
}
