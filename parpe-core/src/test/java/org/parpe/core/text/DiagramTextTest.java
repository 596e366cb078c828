package org.parpe.core.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.parpe.core.diagram.BehaviorEdits;
import org.parpe.core.diagram.Diagrams;
import org.parpe.core.diagram.Layouts;
import org.parpe.core.edit.EditRefused;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;

/**
 * The translators' check of the diagrams' words ({@link DiagramMsg}) and of the diagram and
 * section editors' refusals ({@link EditMsg}), docs/cli.md "Translating PARPE":
 * {@code mvn -B -o -pl parpe-core test -Dtest=DiagramTextTest}.
 */
class DiagramTextTest {
    private static final String SCRIPT = """
            <program>
              <robot><structure><legs elements="0..3"/></structure></robot>
              <main><walk/></main>
              <behaviors><walk><wave group="legs" phase="0.25"/></walk></behaviors>
              <automata><wave states="up, down" times="1, 1"/></automata>
              <states><up angles="30"/><down angles="-30"/></states>
            </program>
            """;

    @Test
    void everyBundleHasEveryKeyNoOtherAndTheEnglishPlaceholders() {
        List<String> problems = BundleCheck.problems(DiagramMsg.BUNDLE, List.of(DiagramMsg.values()));
        problems.addAll(BundleCheck.problems(EditMsg.BUNDLE, List.of(EditMsg.values())));
        assertEquals(List.of(), problems, "fix the bundles of DiagramMsg and EditMsg:\n" + String.join("\n", problems));
    }

    @Test
    void everyKeyIsUsedByTheCode() throws IOException {
        StringBuilder code = new StringBuilder();
        try (Stream<Path> s = Files.walk(Path.of("src/main/java"))) {
            for (Path p : (Iterable<Path>) s.filter(p -> p.toString().endsWith(".java"))::iterator) {
                code.append(Files.readString(p));
            }
        }
        assertEquals(List.of(), BundleCheck.unusedIn(code, List.of(DiagramMsg.values()), "DiagramMsg."), "DiagramMsg keys no code uses");
        assertEquals(List.of(), BundleCheck.unusedIn(code, List.of(EditMsg.values()), "EditMsg."), "EditMsg keys no code uses");
    }

    /**
     * Issue 38: a ring's words and an edit's refusal come out in the IDE's language. The refusal
     * is made while English is chosen and shown after German is: it is formatted when shown.
     */
    @Test
    void aRingsWordsAndAnEditsRefusalAreInTheUsersLanguage() {
        Program p = ScriptLoader.loadText(Path.of("walk.xml"), SCRIPT, Map.of()).program();
        EditRefused refused = assertThrows(EditRefused.class, () -> BehaviorEdits.addEntry(SCRIPT, p, "run"));
        assertEquals("there is no behavior 'run'", refused.getMessage());
        String english = Layouts.ring(Diagrams.ring(p, p.automaton("wave").orElseThrow())).svg();
        assertTrue(english.contains(">one cycle<") && english.contains(">automaton wave<"), english);
        Lang.use(Locale.GERMAN);
        try {
            assertEquals("es gibt kein Verhalten 'run'", refused.getMessage());
            String ring = Layouts.ring(Diagrams.ring(p, p.automaton("wave").orElseThrow())).svg();
            assertTrue(ring.contains(">ein Zyklus<") && ring.contains(">Automat wave<") && ring.contains("dauert 1 s"), ring);
            assertTrue(ring.contains("Zustände im Uhrzeigersinn ab oben, Bogenlänge = Dauer des Zustands"), ring);
        } finally {
            Lang.use(Locale.ENGLISH);
        }
    }
}
