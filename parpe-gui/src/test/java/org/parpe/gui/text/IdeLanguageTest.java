package org.parpe.gui.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.gui.automation.LaunchOptions;

/** Which language the IDE speaks (docs/decisions.md, "Language of the IDE"): --lang, then the preference, then the environment. */
class IdeLanguageTest {
    private static final Map<String, String> GERMAN_DESKTOP = Map.of("LANG", "de_DE.UTF-8");

    @Test
    void langBeatsThePreferenceWhichBeatsTheEnvironment() {
        assertEquals(Locale.JAPANESE, IdeLanguage.choose("ja", "es", GERMAN_DESKTOP::get));
        assertEquals(Locale.forLanguageTag("es"), IdeLanguage.choose(null, "es", GERMAN_DESKTOP::get));
        assertEquals(Locale.GERMAN, IdeLanguage.choose(null, null, GERMAN_DESKTOP::get));
        assertEquals(Locale.GERMAN, IdeLanguage.choose(null, "", GERMAN_DESKTOP::get), "As the System: no preference");
        assertEquals(Locale.ENGLISH, IdeLanguage.choose(null, null, Map.of("LC_ALL", "C.UTF-8", "LANG", "de_DE.UTF-8")::get));
        assertEquals(Locale.GERMAN, IdeLanguage.choose(null, "fr", GERMAN_DESKTOP::get), "a preference PARPE cannot speak is none");
    }

    @Test
    void anUnknownLangIsAUsageErrorThatNamesTheLanguagesSpoken() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> IdeLanguage.choose("fr", null, GERMAN_DESKTOP::get));
        assertEquals("unknown language 'fr'; PARPE speaks en, de, es, ja", e.getMessage());
    }

    /**
     * {@code LC_ALL=ja_JP.UTF-8} where that locale is not installed (a fresh container): Java
     * falls back to ASCII, and {@code parpe gui}'s messages came out as {@code ?}; they are UTF-8,
     * as the command line's are.
     */
    @Test
    void messagesAreUtf8WhereTheLocaleSaysSoThoughItIsNotInstalled() throws Exception {
        ProcessBuilder pb = new ProcessBuilder(java.nio.file.Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), "org.parpe.gui.Main", "--lang", "ja", "--run-for", "x");
        pb.environment().put("LC_ALL", "ja_JP.UTF-8");
        pb.redirectErrorStream(true);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertEquals(2, p.waitFor());
        assertTrue(out.contains("--run-for は 0 以上の秒数でなければなりません"), out);
    }

    @Test
    void parpeGuiTakesLang() {
        assertEquals(Path.of("x.xml"), LaunchOptions.parse(List.of("x.xml", "--lang", "de")).file());
        assertEquals("de", LaunchOptions.langOption(List.of("x.xml", "--lang", "de")));
        assertEquals("ja", LaunchOptions.langOption(List.of("--lang=ja")));
        assertTrue(LaunchOptions.usage().contains("--lang=CODE"), LaunchOptions.usage());
    }
}
