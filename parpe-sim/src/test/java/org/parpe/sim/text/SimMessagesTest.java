package org.parpe.sim.text;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.BundleCheck;

/**
 * The translators' check of the simulator's own messages (docs/cli.md, "Translating PARPE"):
 * {@code mvn -B -o -pl parpe-sim -am test -Dtest=SimMessagesTest -Dsurefire.failIfNoSpecifiedTests=false}.
 */
class SimMessagesTest {

    @Test
    void everyBundleHasEveryKeyNoOtherAndTheEnglishPlaceholders() {
        List<String> problems = BundleCheck.problems(SimMsg.BUNDLE, List.of(SimMsg.values()));
        assertEquals(List.of(), problems, "fix the bundles of org.parpe.sim.text.SimMsg:\n" + String.join("\n", problems));
    }

    @Test
    void everyKeyIsUsedByTheCode() throws IOException {
        StringBuilder code = new StringBuilder();
        try (Stream<Path> s = Files.walk(Path.of("src/main/java"))) {
            for (Path p : (Iterable<Path>) s.filter(p -> p.toString().endsWith(".java")
                    && !p.endsWith("text/SimMsg.java"))::iterator) {
                code.append(Files.readString(p));
            }
        }
        List<String> unused = BundleCheck.unusedIn(code, List.of(SimMsg.values()), "SimMsg.");
        assertEquals(List.of(), unused, "keys no code uses: remove them from SimMsg and every bundle");
    }
}
