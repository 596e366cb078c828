package org.parpe.serial.text;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.BundleCheck;

/**
 * The translators' check of the servo buses' own messages (docs/cli.md, "Translating PARPE"):
 * {@code mvn -B -o -pl parpe-serial -am test -Dtest=SerialMessagesTest -Dsurefire.failIfNoSpecifiedTests=false}.
 */
class SerialMessagesTest {

    @Test
    void everyBundleHasEveryKeyNoOtherAndTheEnglishPlaceholders() {
        List<String> problems = BundleCheck.problems(SerialMsg.BUNDLE, List.of(SerialMsg.values()));
        assertEquals(List.of(), problems, "fix the bundles of org.parpe.serial.text.SerialMsg:\n" + String.join("\n", problems));
    }

    @Test
    void everyKeyIsUsedByTheCode() throws IOException {
        StringBuilder code = new StringBuilder();
        try (Stream<Path> s = Files.walk(Path.of("src/main/java"))) {
            for (Path p : (Iterable<Path>) s.filter(p -> p.toString().endsWith(".java")
                    && !p.endsWith("text/SerialMsg.java"))::iterator) {
                code.append(Files.readString(p));
            }
        }
        List<String> unused = BundleCheck.unusedIn(code, List.of(SerialMsg.values()), "SerialMsg.");
        assertEquals(List.of(), unused, "keys no code uses: remove them from SerialMsg and every bundle");
    }

    /** A warning keeps its words apart from the device's, so both are in the user's language. */
    @Test
    void aWarningAndItsDeviceAreInTheSameLanguage() {
        org.parpe.core.text.Message m = org.parpe.core.text.Message.of(SerialMsg.DID_NOT_ANSWER_READS,
                org.parpe.core.text.Message.of(SerialMsg.WHO_SERVO, 3, 0), 3);
        assertEquals("servo 3 (module 0) did not answer 3 reads; reading it less often", m.format(java.util.Locale.ENGLISH));
        assertEquals("Servo 3 (Modul 0) hat auf 3 Abfragen nicht geantwortet; es wird seltener abgefragt",
                m.format(java.util.Locale.GERMAN));
    }
}
