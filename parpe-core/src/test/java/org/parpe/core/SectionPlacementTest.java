package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;
import org.parpe.core.edit.SectionEdits;

/**
 * Issue 31: the tutorial's "Insert this code" put a lesson's {@code <states>} at the caret, inside
 * whatever element the caret was in. {@link SectionEdits#placeSections} puts sections where they
 * belong: into the script's section of that name, or at the top level. Expected texts are
 * written out by hand.
 */
class SectionPlacementTest {
    private static final String SCRIPT = String.join("\n",
            "<program>",
            "  <robot>",
            "    <structure>",
            "      <snake elements=\"0, 1\"/>",
            "    </structure>",
            "  </robot>",
            "  <states>",
            "    <up angles=\"30\"/>",
            "  </states>",
            "</program>",
            "");

    private static String place(String text, String snippet) {
        return SectionEdits.placeSections(text, "s.xml", snippet).apply(text);
    }

    @Test
    void aSectionTheScriptHasGetsTheSnippetsElementsAfterItsOwn() {
        assertEquals(SCRIPT.replace("    <up angles=\"30\"/>\n", "    <up angles=\"30\"/>\n    <down angles=\"-30\"/>\n"
                        + "    <mid angles=\"0\"/>\n"),
                place(SCRIPT, "<states>\n  <down angles=\"-30\"/>\n  <mid angles=\"0\"/>\n</states>"));
    }

    @Test
    void aSectionTheScriptLacksGoesToTheTopLevelInTheUsualOrder() {
        String expected = SCRIPT.replace("  </robot>\n", "  </robot>\n  <main>\n    <go/>\n  </main>\n"
                + "  <behaviors>\n    <go>\n      <wave group=\"snake\"/>\n    </go>\n  </behaviors>\n");
        assertEquals(expected, place(SCRIPT, "<main>\n  <go/>\n</main>\n<behaviors>\n  <go>\n    <wave group=\"snake\"/>\n"
                + "  </go>\n</behaviors>"));
    }

    @Test
    void aBlankFileGetsAProgram() {
        assertEquals("<?xml version=\"1.0\"?>\n<program>\n  <states>\n    <up angles=\"30\"/>\n  </states>\n</program>\n",
                place("<?xml version=\"1.0\"?>\n", "<states>\n  <up angles=\"30\"/>\n</states>"));
    }

    @Test
    void anElementOfASectionHasNoPlaceOfItsOwn() {
        assertNull(SectionEdits.placeSections(SCRIPT, "s.xml", "<wave states=\"up, down\"/>"));
        assertNull(SectionEdits.placeSections(SCRIPT, "s.xml", "<states>\n  <up angles=\"1\"/>\n</states>\n<wave/>"));
    }
}
