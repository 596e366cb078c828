package org.parpe.core.expr;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Collections;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.model.Control;
import org.parpe.core.model.Interp;
import org.parpe.core.model.MainEntry;
import org.parpe.core.xml.XText;

/** The vocabulary names what the expression compiler and the model implement, no more, no less. */
class VocabularyTest {
    private static final Scope MODULE = new Scope(Scope.Kind.MODULE, Map.of(), Map.of(), Map.of(), Set.of(), Map.of(),
            Set.of(), Scope.SensorCatalog.NONE);

    @Test
    void functionsAreThoseTheCompilerEvaluatesWithTheirArities() {
        Map<String, Integer> implemented = new TreeMap<>(Map.of("if", 3, "rand", 0, "sum", Vocabulary.ONE_OR_MORE));
        Arrays.stream(Functions.F1.values()).forEach(f -> implemented.put(f.name().toLowerCase(Locale.ROOT), 1));
        Arrays.stream(Functions.F2.values()).forEach(f -> implemented.put(f.name().toLowerCase(Locale.ROOT), 2));
        Map<String, Integer> declared = new TreeMap<>();
        Vocabulary.functions().forEach(f -> declared.put(f, Vocabulary.arity(f)));
        assertEquals(implemented, declared);
    }

    @Test
    void everyFunctionCompilesWithItsArityAndIsReserved() {
        for (String f : Vocabulary.functions()) {
            int n = Vocabulary.arity(f) < 0 ? 3 : Vocabulary.arity(f);
            String text = f + "(" + String.join(", ", Collections.nCopies(n, "0.5")) + ")";
            DiagnosticList d = new DiagnosticList();
            assertNotNull(ExprCompiler.compile(XText.detached(text, new SourcePos("t", 1, 1)), MODULE, d),
                    text + ": " + d.all());
            assertTrue(Vocabulary.isReserved(f), f);
        }
    }

    @Test
    void logicalVariablesAndConstantsCompileWhereAllAreVisible() {
        for (String v : Vocabulary.LOGICAL_VARIABLES) {
            DiagnosticList d = new DiagnosticList();
            assertNotNull(ExprCompiler.compile(XText.detached("$" + v, new SourcePos("t", 1, 1)), MODULE, d), v);
        }
        for (String c : Vocabulary.CONSTANTS) {
            DiagnosticList d = new DiagnosticList();
            assertNotNull(ExprCompiler.compile(XText.detached(c, new SourcePos("t", 1, 1)), MODULE, d), c);
        }
    }

    @Test
    void wordsOfTheModelsEnumsAreTheVocabularys() {
        assertEquals(Vocabulary.INTERP_WORDS, Arrays.stream(Interp.values()).map(Interp::word).toList());
        assertEquals(Vocabulary.CONTROL_TYPES,
                Arrays.stream(Control.ControlType.values()).map(Control.ControlType::word).toList());
        for (String type : Vocabulary.CONTROL_TYPES) {
            assertNotNull(Vocabulary.Element.control(type), type);
        }
    }

    @Test
    void aMirroredGroupIsWrittenWithTheMirrorSign() {
        assertEquals(new MainEntry.GroupRef("legs", true), MainEntry.GroupRef.parse(" ! legs "));
        assertEquals(new MainEntry.GroupRef("legs", false), MainEntry.GroupRef.parse("legs "));
    }
}
