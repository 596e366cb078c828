package org.parpe.sim.bridge;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The part names every target format takes (docs/bridges.md): letters, digits, {@code _ . -}, not starting with a digit. */
class ExportNameTest {
    @Test
    void namesOfLettersDigitsUnderscoresDotsAndDashesAreTaken() {
        for (String ok : new String[] {"seg0", "_hub", "left.leg-2", "A"}) {
            assertTrue(Export.validName(ok), ok);
        }
    }

    @Test
    void emptyNamesLeadingDigitsAndOtherCharactersAreRefused() {
        for (String bad : new String[] {"", "0seg", "-a", ".a", "a b", "a/b", "a\"b", "é"}) {
            assertFalse(Export.validName(bad), bad);
        }
    }
}
