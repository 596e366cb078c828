package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;

/**
 * Issue 32: a diagnostic carries the character offset of its place, which the editor's markers
 * and the grid's cells use instead of turning line and column into an offset. Over every error
 * case of the conformance suites, the offset is the place line and column name (a column past
 * its line's end: the line's end), so the markers stay where they were.
 */
class DiagnosticOffsetTest {
    static Stream<Path> errorCases() throws Exception {
        return Conformance.cases().stream().filter(dir -> {
            try {
                return Conformance.args(dir).get(0).equals("check");
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("errorCases")
    void theOffsetIsThePlaceOfLineAndColumn(Path dir) throws Exception {
        LoadResult r = ScriptLoader.load(dir.resolve(Conformance.args(dir).get(1)), Map.of());
        List<Diagnostic> placed = r.diagnostics().stream().filter(d -> d.pos().offset() >= 0).toList();
        assertTrue(!placed.isEmpty(), "no diagnostic with an offset: " + r.diagnostics());
        for (Diagnostic d : placed) {
            String text = Files.readString(Path.of(d.pos().file()));
            text = text.startsWith("\uFEFF") ? text.substring(1) : text;
            int lineStart = 0;
            for (int l = 1; l < d.pos().line(); l++) {
                lineStart = text.indexOf('\n', lineStart) + 1;
            }
            int lineEnd = text.indexOf('\n', lineStart);
            lineEnd = lineEnd < 0 ? text.length() : lineEnd;
            assertEquals(Math.min(lineStart + d.pos().column() - 1, lineEnd), d.pos().offset(), d.format());
        }
    }
}
