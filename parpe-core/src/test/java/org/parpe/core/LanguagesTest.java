package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.text.Lang;

/**
 * Every load-time diagnostic of {@link DiagnosticsTest}'s cases comes from the bundles: it has a
 * key (no text bypasses the bundles), reads differently in German, Spanish and Japanese than in
 * English. (That {@code parpe check} prints the same places in every language is
 * {@code CheckLanguagesTest} of parpe-cli.)
 */
class LanguagesTest {

    static java.util.stream.Stream<org.junit.jupiter.params.provider.Arguments> cases() {
        return DiagnosticsTest.cases();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void sameLocatedErrorsOnlyTheTextDiffers(String name, String text, String words) {
        List<Diagnostic> found = ScriptLoader.loadText(Path.of("case.xml"), text, Map.of()).diagnostics();
        assertFalse(found.isEmpty(), name);
        for (Diagnostic d : found) {
            assertNotNull(d.text().key(), () -> "a text outside the bundles: " + d.format());
            String english = d.text().format(Locale.ENGLISH);
            for (Locale l : Lang.SUPPORTED.subList(1, Lang.SUPPORTED.size())) {
                String translated = d.text().format(l);
                assertNotEquals(english, translated, () -> l + " has the English text of " + d.format());
            }
        }
    }
}
