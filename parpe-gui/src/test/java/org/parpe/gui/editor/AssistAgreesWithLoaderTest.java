package org.parpe.gui.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;

/**
 * The editor's completion offers what the loader accepts, nothing more and nothing less: at
 * every place of a script, each attribute name is written into the tag and loaded; the loader
 * must reject exactly those the completion does not offer. Functions, logical variables and
 * constants offered in an expression must all compile. (Before the vocabulary was shared, the
 * completion missed asinh, acosh and atanh and offered "elements" inside {@code <actuators>}.)
 */
class AssistAgreesWithLoaderTest {
    /** A script without errors; {@code @NAME} marks where an attribute is written into a tag. */
    private static final String TEMPLATE = """
            <program @PROGRAM>
              <robot @ROBOT>
                <structure @ROBOT_PART>
                  <legs elements="0..1" @GROUP/>
                </structure>
                <sensors>
                  <angle elements="0" @SENSOR/>
                </sensors>
                <actuators>
                </actuators>
              </robot>
              <include file="inc.xml" @INCLUDE/>
              <parameters @SECTION>
                <speed value="1" @PARAMETER/>
              </parameters>
              <controls>
                <s type="slider" min="0" max="1" value="0" @SLIDER/>
                <t value="0" @TEXT_CONTROL/>
                <r type="radio" values="a, b" value="a" @RADIO/>
              </controls>
              <states>
                <up angles="1" @STATE/>
              </states>
              <automata>
                <go states="up, down" @AUTOMATON/>
              </automata>
              <behaviors>
                <walk macros="g" @BEHAVIOR>
                  <go group="g" @INSTANCE/>
                  <if cond="$r == a" @CONDITIONAL>
                    <go group="g"/>
                  </if>
                </walk>
              </behaviors>
              <main cycles="1" @MAIN>
                <walk g="legs" time="1" @ENTRY/>
              </main>
            </program>
            """;
    private static final Pattern MARK = Pattern.compile("@([A-Z_]+)");

    @TempDir
    Path dir;
    private Path main;

    @BeforeEach
    void files() throws IOException {
        main = dir.resolve("main.xml");
        Files.writeString(dir.resolve("inc.xml"), "<program><states><down angles=\"-1\"/></states></program>");
    }

    @Test
    void templateLoadsWithoutErrors() {
        LoadResult r = ScriptLoader.loadText(main, without(TEMPLATE), Map.of());
        assertEquals("[]", r.errors().toString());
    }

    @Test
    void everyPlaceOffersExactlyTheAttributesTheLoaderAccepts() {
        Set<String> universe = new TreeSet<>(Set.of("zz", "g", "elements2"));
        for (Vocabulary.Element e : Vocabulary.Element.values()) {
            universe.addAll(e.attributes());
        }
        Set<String> controlsAccepted = new TreeSet<>();
        Set<String> controlsOffered = null;
        Matcher m = MARK.matcher(TEMPLATE);
        int places = 0;
        while (m.find()) {
            String place = m.group(1);
            Set<String> offered = offered(m.start());
            Set<String> accepted = new TreeSet<>();
            for (String attr : universe) {
                if (accepts(m.start(), attr)) {
                    accepted.add(attr);
                }
            }
            assertTrue(!accepted.contains("zz"), place + " accepts any attribute: the check of this test is broken");
            if (Set.of("SLIDER", "TEXT_CONTROL", "RADIO").contains(place)) {
                controlsAccepted.addAll(accepted);
                controlsOffered = offered;
            } else {
                assertEquals(accepted, offered, "attributes offered at " + place + " vs accepted by the loader");
            }
            places++;
        }
        // The type of a control may not be written yet: offer what some type accepts.
        assertEquals(controlsAccepted, controlsOffered, "attributes offered on a control vs accepted by the loader");
        assertEquals(18, places);
    }

    @Test
    void everyFunctionVariableAndConstantOfferedCompilesAndNoFunctionIsMissing() {
        String text = without(TEMPLATE);
        int at = text.indexOf("<up angles=\"") + "<up angles=\"".length();
        Map<String, String> offered = ParslAssistProcessor.candidates(XmlContext.at(text, at), NameIndex.of(text));
        Set<String> functions = new TreeSet<>();
        offered.forEach((word, what) -> {
            String expr = switch (what) {
                case "function" -> call(word);
                case "logical variable", "constant", "control", "parameter", "radio word" -> word;
                default -> throw new AssertionError("unexpected offer " + word + " (" + what + ")");
            };
            if (what.equals("function")) {
                functions.add(word);
            }
            String script = without(TEMPLATE).replace("<up angles=\"1\"", "<up angles=\"" + expr + "\"");
            assertEquals("[]", ScriptLoader.loadText(main, script, Map.of()).errors().toString(), expr);
        });
        assertEquals(new TreeSet<>(Vocabulary.functions()), functions);
        assertTrue(functions.containsAll(Set.of("asinh", "acosh", "atanh")), "the functions the editor had missed");
    }

    @Test
    void namesOfALoadedProgramIncludeThoseOfItsIncludes() {
        LoadResult r = ScriptLoader.loadText(main, without(TEMPLATE), Map.of());
        NameIndex loaded = NameIndex.of(r.program());
        assertTrue(loaded.states().contains("down"), "the included state");
        assertEquals(Set.of("up", "down"), NameIndex.of("<program><states><up/></states></program>").with(loaded).states());
        assertEquals(java.util.List.of("g"), loaded.macros("walk"));
        assertEquals(Set.of("a", "b"), loaded.radioWords());
        assertEquals(Set.of("legs", "all"), loaded.groups());
    }

    private static String call(String function) {
        int arity = Vocabulary.arity(function);
        return function + "(" + String.join(", ", java.util.Collections.nCopies(arity < 0 ? 2 : arity, "0.5")) + ")";
    }

    private Set<String> offered(int mark) {
        String text = without(TEMPLATE.substring(0, mark));
        String whole = text + without(TEMPLATE.substring(mark));
        return new TreeSet<>(ParslAssistProcessor.candidates(XmlContext.at(whole, text.length()), NameIndex.of(whole))
                .keySet());
    }

    /** Whether the loader takes {@code attr} written at {@code mark}: no problem is placed on its name. */
    private boolean accepts(int mark, String attr) {
        int tagStart = TEMPLATE.lastIndexOf('<', mark);
        if (Pattern.compile("\\s" + attr + "=").matcher(TEMPLATE.substring(tagStart, mark)).find()) {
            return true; // already written in the template, which loads without errors
        }
        String before = without(TEMPLATE.substring(0, mark));
        String script = before + "\n" + attr + "=\"1\" " + without(TEMPLATE.substring(mark + mark(mark).length()));
        int line = (int) before.chars().filter(c -> c == '\n').count() + 2;
        for (Diagnostic d : ScriptLoader.loadText(main, script, Map.of()).diagnostics()) {
            if (d.severity() == Severity.ERROR && d.pos().line() == line && d.pos().column() == 1
                    && d.pos().file().equals(main.toString())) {
                return false;
            }
        }
        return true;
    }

    private static String mark(int at) {
        Matcher m = MARK.matcher(TEMPLATE);
        m.find(at);
        return m.group();
    }

    private static String without(String text) {
        return MARK.matcher(text).replaceAll("");
    }
}
