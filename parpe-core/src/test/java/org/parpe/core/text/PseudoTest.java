package org.parpe.core.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.text.MessageFormat;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.ResourceBundle;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The pseudo-language {@code qps} (docs/decisions.md, "The pseudo-language"). */
class PseudoTest {

    @AfterEach
    void english() {
        Lang.use(Locale.ENGLISH);
    }

    @Test
    void lettersAccentedTextBracketedAndFortyPercentLonger() {
        assertEquals("[Öþéñ fîłé… ~~~]", Pseudo.text("Open file\u2026"));
        assertEquals("[ÖK~]", Pseudo.text("OK"));
        assertEquals("", Pseudo.text(""));
        for (String english : List.of("Run", "Export Program as C/Arduino\u2026", "a", "Sweep / Optimise")) {
            String p = Pseudo.text(english);
            assertTrue(p.length() >= english.length() * 1.4, p + " is 40 % longer than " + english);
            assertTrue(p.startsWith("[") && p.endsWith("]"), p);
        }
    }

    @Test
    void placeholdersQuotesAndApostrophesStayAsTheyAre() {
        assertEquals("[ĝröüþ ''{0}'' îš ñöt đéfîñéđ{1} ~~~~~~~~~~~~]",
                Pseudo.text("group ''{0}'' is not defined{1}"));
        String p = Pseudo.text("{0,choice,0#no files|1#one file|1<{0} files} in {1}");
        assertTrue(p.contains("{0,choice,0#no files|1#one file|1<{0} files} îñ {1}"), p);
        assertEquals("[3 ƀý 2 fîłéš ~~~~]", Pseudo.text("3 by 2 files"));
        // quoted braces are text, not a placeholder, and still format as braces
        assertEquals("['{'ƀ'}' ~~]", Pseudo.text("'{'b'}'"));
        assertEquals("[{ƀ} 5 ~~~~]", new MessageFormat(Pseudo.text("'{'b'}' {0}"), Locale.ROOT).format(new Object[] {"5"}));
    }

    @Test
    void mnemonicsAndAcceleratorsKeepTheirKeys() {
        assertEquals("[&Fîłé ~]", Pseudo.text("&File"));
        assertEquals("[&Såvé ~]\tCtrl+S", Pseudo.text("&Save\tCtrl+S"));
        assertEquals("[Šé&wéþ ~~]", Pseudo.text("Se&wep"));
        assertEquals("[R && D ~~]", Pseudo.text("R && D"));
    }

    @Test
    void everyMessageOfTheCoreIsAValidPatternWithTheEnglishPlaceholders() {
        ResourceBundle english = Message.bundle(Msg.BUNDLE, Locale.ENGLISH);
        List<String> wrong = new ArrayList<>();
        for (Msg m : Msg.values()) {
            String e = english.getString(m.name());
            String p = Pseudo.text(e);
            try {
                new MessageFormat(p, Locale.ROOT);
            } catch (IllegalArgumentException ex) {
                wrong.add(m + ": " + p + ": " + ex.getMessage());
                continue;
            }
            if (!BundleCheck.placeholders(p).equals(BundleCheck.placeholders(e)) || p.equals(e)) {
                wrong.add(m + ": " + p);
            }
        }
        assertEquals(List.of(), wrong);
    }

    @Test
    void chosenByQpsEveryLookupServesThePseudoText() {
        assertEquals(Lang.PSEUDO, Lang.parse("qps"));
        assertEquals(Lang.PSEUDO, Lang.parse("qps-ploc"));
        assertFalse(Lang.SUPPORTED.contains(Lang.PSEUDO), "not offered to students");
        assertEquals("en, de, es, ja", Lang.codes());
        assertEquals(Locale.ENGLISH, Lang.fromEnvironment(v -> v.equals("LANG") ? "qps" : null), "only --lang chooses it");
        Message m = Message.of(Msg.GROUP_NOT_DEFINED, "legs", Message.of(Msg.DID_YOU_MEAN, "leg"));
        Lang.use(Lang.PSEUDO);
        assertEquals(Lang.PSEUDO, Lang.current());
        String shown = m.toString();
        // the nested message is pseudo too: its brackets show where it was glued in
        assertEquals("[ĝröüþ 'legs' îš ñöt đéfîñéđ[ (đîđ ýöü méåñ 'leg'?) ~~~~~~~~~] ~~~~~~~~~~~~]", shown);
        assertNotEquals(m.format(Locale.ENGLISH), shown);
        assertEquals(Pseudo.text(Message.pattern(Msg.DID_YOU_MEAN, Locale.ENGLISH)),
                Message.bundle(Msg.BUNDLE, Lang.PSEUDO).getString(Msg.DID_YOU_MEAN.name()));
        assertTrue(Message.bundle(Msg.BUNDLE, Lang.PSEUDO).containsKey(Msg.DID_YOU_MEAN.name()));
    }
}
