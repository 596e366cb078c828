package org.parpe.core.load;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.Diagnostic;

/**
 * Issue 19, item 8: {@code ScriptLoader.read} is the only step that reads files; {@code bind}
 * loads what it read with any parameter values, as {@code loadText} would have on those files.
 */
class ParsedScriptTest {
    private static final String MAIN = """
            <program>
              <robot file="body.xml"/>
              <parameters><last value="2" min="1" max="9"/></parameters>
              <include file="gait.xml"/>
              <main><go/></main>
            </program>
            """;

    @TempDir
    Path dir;

    private Path write() throws Exception {
        Files.writeString(dir.resolve("body.xml"), "<robot><structure><body elements=\"0..last\"/></structure></robot>");
        Files.writeString(dir.resolve("gait.xml"), """
                <program>
                  <behaviors><go><wave group="body" phase="0.2" period="1"/></go></behaviors>
                  <automata><wave states="up"/></automata>
                  <states><up angles="30"/></states>
                </program>
                """);
        return dir.resolve("main.xml");
    }

    @Test
    void bindReadsNoFileAndTakesEachRunsValues() throws Exception {
        Path main = write();
        ParsedScript read = ScriptLoader.read(main, MAIN);
        assertEquals(List.of(main, dir.resolve("gait.xml"), dir.resolve("body.xml")), read.files());
        Files.delete(dir.resolve("gait.xml"));
        Files.delete(dir.resolve("body.xml"));
        LoadResult three = ScriptLoader.bind(read, Map.of("last", 2.0));
        LoadResult six = ScriptLoader.bind(read, Map.of("last", 5.0));
        assertTrue(three.ok() && six.ok(), three.diagnostics() + " " + six.diagnostics());
        assertArrayEquals(new int[] {0, 1, 2}, three.program().robot().moduleIds());
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5}, six.program().robot().moduleIds());
        assertEquals(read.files(), six.files());
        String again = ScriptLoader.loadText(main, MAIN, Map.of()).errors().toString();
        assertTrue(again.contains("cannot read included file") && again.contains("cannot read robot file"),
                "the files are gone for a new read: " + again);
    }

    @Test
    void bindReportsWhatReadingFoundInTheSameOrderAsLoadText() throws Exception {
        Path main = write();
        Files.writeString(dir.resolve("body.xml"), "<robot><structure><body elements=\"0..last\"/></structure>");
        String text = MAIN.replace("<main>", "<bogus/><main>");
        List<String> once = ScriptLoader.loadText(main, text, Map.of("last", 3.0)).diagnostics().stream()
                .map(Diagnostic::format).toList();
        List<String> bound = ScriptLoader.bind(ScriptLoader.read(main, text), Map.of("last", 3.0)).diagnostics()
                .stream().map(Diagnostic::format).toList();
        assertEquals(once, bound);
        assertTrue(once.size() >= 2 && once.get(0).contains("main.xml") && once.get(1).contains("body.xml"), once.toString());
    }
}
