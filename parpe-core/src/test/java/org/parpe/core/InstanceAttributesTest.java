package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.RecordComponent;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.diagram.Diagrams;
import org.parpe.core.diagram.Layouts;
import org.parpe.core.export.CProgram;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Program;
import org.parpe.core.print.ProgramPrinter;

/**
 * Issue 32, trial changes: an attribute of automaton instances reaches every place that reads
 * instances. The record {@link Instance}, the vocabulary's {@code INSTANCE} element and its
 * expression attributes name the same attributes; each one written with two values gives two
 * printed scripts, two swimlane diagrams and two exported C programs (a place that drops it gives
 * one). The gait-table expansion reads or refuses each by constructing an Instance with all of
 * them, which does not compile until a new one is placed.
 */
class InstanceAttributesTest {
    /** What an instance holds that is no attribute of its own: the automaton (its element's name), the bound group, the place. */
    private static final List<String> NOT_ATTRIBUTES = List.of("automaton", "on", "pos");

    private static List<String> expressionAttributes() {
        return Vocabulary.Element.INSTANCE.attributes().stream().filter(a -> !a.equals("group")).toList();
    }

    @Test
    void theRecordAndTheVocabularyNameTheSameAttributes() {
        List<String> components = Arrays.stream(Instance.class.getRecordComponents()).map(RecordComponent::getName)
                .filter(n -> !NOT_ATTRIBUTES.contains(n)).sorted().toList();
        assertEquals(Vocabulary.Element.INSTANCE.attributes().stream().sorted().toList(), components);
        assertTrue(Vocabulary.EXPRESSION_ATTRIBUTES.containsAll(expressionAttributes()),
                "an instance's attributes but group are expressions: " + Vocabulary.EXPRESSION_ATTRIBUTES);
    }

    @Test
    void everyAttributeReachesThePrinterTheDiagramAndTheExport() {
        for (String attribute : expressionAttributes()) {
            Program two = load(attribute, "2");
            Program three = load(attribute, "3");
            assertNotEquals(ProgramPrinter.print(two), ProgramPrinter.print(three), attribute + ": the printer drops it");
            assertNotEquals(Layouts.lanes(Diagrams.swimlanes(two, two.behaviors().get(0))).svg(),
                    Layouts.lanes(Diagrams.swimlanes(three, three.behaviors().get(0))).svg(),
                    attribute + ": the swimlane diagram drops it");
            assertNotEquals(CProgram.of(two, 0.01).source(), CProgram.of(three, 0.01).source(),
                    attribute + ": the C export drops it");
        }
    }

    private static Program load(String attribute, String value) {
        String text = "<program><robot><structure><b elements=\"0, 1\"/></structure></robot>\n"
                + "<main><go/></main><behaviors><go><wave group=\"b\" " + attribute + "=\"" + value + "\"/></go></behaviors>\n"
                + "<automata><wave states=\"up, down\"/></automata>\n"
                + "<states><up angles=\"30\"/><down angles=\"-30\"/></states></program>";
        LoadResult r = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of());
        assertTrue(r.ok(), () -> attribute + ": " + r.diagnostics());
        return r.program();
    }
}
