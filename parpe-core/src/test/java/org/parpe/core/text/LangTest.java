package org.parpe.core.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.Locale;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** How PARPE chooses its language (docs/decisions.md, "Language of messages"). */
class LangTest {

    private static Locale env(Map<String, String> vars) {
        return Lang.fromEnvironment(vars::get);
    }

    @Test
    void lcAllBeatsLcMessagesBeatsLang() {
        assertEquals(Locale.JAPANESE, env(Map.of("LC_ALL", "ja_JP.UTF-8", "LC_MESSAGES", "de_DE.UTF-8", "LANG", "es_ES.UTF-8")));
        assertEquals(Locale.GERMAN, env(Map.of("LC_MESSAGES", "de_DE.UTF-8", "LANG", "es_ES.UTF-8")));
        assertEquals(Locale.forLanguageTag("es"), env(Map.of("LANG", "es_MX.UTF-8")));
    }

    @Test
    void anEmptyVariableIsUnsetAndTheFirstSetOneDecides() {
        assertEquals(Locale.GERMAN, env(Map.of("LC_ALL", "", "LANG", "de_AT.ISO-8859-1")));
        // POSIX: a set LC_MESSAGES decides even when it names a language PARPE lacks; not the LANG behind it
        assertEquals(Locale.ENGLISH, env(Map.of("LC_MESSAGES", "fr_FR.UTF-8", "LANG", "de_DE.UTF-8")));
    }

    @Test
    void nothingSetCOrPosixOrAnotherLanguageIsEnglish() {
        assertEquals(Locale.ENGLISH, env(Map.of()));
        assertEquals(Locale.ENGLISH, env(Map.of("LANG", "C")));
        assertEquals(Locale.ENGLISH, env(Map.of("LANG", "C.UTF-8")));
        assertEquals(Locale.ENGLISH, env(Map.of("LC_ALL", "POSIX")));
        assertEquals(Locale.ENGLISH, env(Map.of("LANG", "pt_BR.UTF-8")));
        assertEquals(Locale.JAPANESE, env(Map.of("LANG", "ja_JP.eucJP@modifier")));
    }

    @Test
    void theCodesOfLangOption() {
        assertEquals(Locale.GERMAN, Lang.parse("de"));
        assertEquals(Locale.GERMAN, Lang.parse("DE-de"));
        assertEquals(Locale.JAPANESE, Lang.parse("ja_JP"));
        assertEquals(Locale.ENGLISH, Lang.parse("en"));
        assertNull(Lang.parse("fr"));
        assertNull(Lang.parse(""));
        assertEquals("en, de, es, ja", Lang.codes());
    }

    @Test
    void englishStaysEnglishOnAMachineWhoseDefaultLocaleIsGerman() {
        Locale before = Locale.getDefault();
        try {
            Locale.setDefault(Locale.GERMAN);
            Message m = Message.of(Msg.GROUP_NOT_DEFINED, "legs", Message.of(Msg.DID_YOU_MEAN, "leg"));
            assertEquals("group 'legs' is not defined (did you mean 'leg'?)", m.format(Locale.ENGLISH));
            assertEquals("Gruppe 'legs' ist nicht definiert (meintest du 'leg'?)", m.format(Locale.GERMAN));
            assertEquals("グループ「legs」は定義されていません（「leg」のことですか？）", m.format(Locale.JAPANESE));
            // unless a program's entry point chose a language, PARPE speaks English
            assertEquals(m.format(Locale.ENGLISH), m.toString());
        } finally {
            Locale.setDefault(before);
        }
    }

    @Test
    void argumentsStayAsWrittenInEveryLanguage() {
        // MessageFormat would write 65535 as 65.535 in German if it were given a number
        Message m = Message.of(Msg.MODULE_ID_TOO_LARGE, "70000", 65535);
        assertEquals("die Modulnummer 70000 ist zu groß: Modulnummern sind ganze Zahlen 0..65535"
                + " (PARSL 1.0.1 Abschnitt 13 Regel 23)", m.format(Locale.GERMAN));
    }
}
