package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
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
 * The PARSL conformance suite as a golden test of the core: every run case's trace matches
 * the reference within 1e-6, every error case reports a diagnostic on each expected line.
 * PARPE's own cases (spec/conformance-parpe) must also match the expected text exactly. (Both
 * suites also run through ./parpe and spec/conformance/run.sh in the CLI's integration-test phase.)
 */
class ConformanceTest {
    static Stream<Path> cases() throws Exception {
        return Conformance.cases().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void conformance(Path dir) throws Exception {
        List<String> args = Conformance.args(dir);
        if (args.get(0).equals("check")) {
            List<String> lines = Files.readAllLines(dir.resolve("expected.txt"));
            LoadResult r = ScriptLoader.load(dir.resolve(args.get(1)), Map.of());
            assertEquals("1", lines.get(0).trim(), "every error case of the suite expects exit code 1");
            assertFalse(r.ok(), "script should not load: " + dir);
            for (String line : lines.subList(1, lines.size())) {
                int n = Integer.parseInt(line.trim());
                assertTrue(r.errors().stream().anyMatch(d -> d.pos().line() == n),
                        "no error at line " + n + "; got " + r.diagnostics().stream().map(Diagnostic::format).toList());
            }
            return;
        }
        Conformance.Outcome out = Conformance.run(dir, args);
        assertTrue(out.loaded(), "does not load: " + out.diagnostics());
        String expected = Files.readString(dir.resolve("expected.csv"));
        assertNull(Conformance.compare(expected, out.trace()));
        if (dir.startsWith(Conformance.PARPE_CASES)) {
            // PARPE's own cases are derived exactly from the rules: the text must match too (§13 rule 23)
            assertEquals(expected.replace("\r\n", "\n"), out.trace(), "the trace text of " + dir.getFileName());
        }
    }
}
