package org.parpe.gui.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.Lang;

/**
 * Completion explains PARSL's words in the IDE's language and offers them as they are written
 * (issue 38: "the editor's hover help and completion explain them in the user's language").
 */
class AssistLanguageTest {
    private static final String SCRIPT = "<program><robot><structure><legs elements=\"0..3\"/></structure></robot>"
            + "<states><up angles=\"30\"/></states><automata><wave states=\"up\"/></automata></program>";

    @AfterEach
    void english() {
        Lang.use(Locale.ENGLISH);
    }

    @Test
    void sectionsAndNamesAreExplainedInGermanAndOfferedInEnglish() {
        Lang.use(Locale.GERMAN);
        Map<String, String> sections = ParslAssistProcessor.candidates(
                new XmlContext(List.of("program"), XmlContext.Kind.ELEMENT_NAME, "", "", ""), NameIndex.of(SCRIPT));
        assertEquals("Zielwinkel in Grad", sections.get("states"));
        assertEquals("Verhalten nacheinander", sections.get("main"));
        Map<String, String> values = ParslAssistProcessor.candidates(new XmlContext(List.of("program", "behaviors", "walk"),
                XmlContext.Kind.ATTRIBUTE_VALUE, "wave", "group", ""), NameIndex.of(SCRIPT));
        assertEquals("Gruppe", values.get("legs"));
        Map<String, String> words = ParslAssistProcessor.candidates(new XmlContext(List.of("program", "states"),
                XmlContext.Kind.ATTRIBUTE_VALUE, "up", "angles", ""), NameIndex.of(SCRIPT));
        assertEquals("Funktion", words.get("sin"));
        assertEquals("logische Variable", words.get("$phase"));
    }

    @Test
    void japaneseExplainsTheSameWords() {
        Lang.use(Locale.JAPANESE);
        Map<String, String> sections = ParslAssistProcessor.candidates(
                new XmlContext(List.of("program"), XmlContext.Kind.ELEMENT_NAME, "", "", ""), NameIndex.of(SCRIPT));
        assertEquals("目標角度 (度)", sections.get("states"));
    }
}
