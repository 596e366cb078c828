package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.core.print.ProgramPrinter;

/** Parse → print → parse gives an equal model, for every example and every conformance program. */
class RoundTripTest {
    static Stream<Path> scripts() throws Exception {
        List<Path> all = new ArrayList<>(Examples.all());
        for (Path c : Conformance.cases()) {
            if (!Conformance.args(c).get(0).equals("check")) {
                all.add(c.resolve("program.xml"));
            }
        }
        return all.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scripts")
    void printThenParseGivesTheSameModel(Path file) {
        LoadResult first = ScriptLoader.load(file, Map.of());
        assertNotNull(first.program(), () -> "does not load: " + first.diagnostics());
        String text = ProgramPrinter.print(first.program());
        LoadResult second = ScriptLoader.loadText(file.resolveSibling("printed.xml"), text, Map.of());
        assertNotNull(second.program(), () -> "printed text does not load: " + second.diagnostics() + "\n" + text);
        assertNull(ModelEquality.diff(first.program(), second.program(), "program"), text);
        assertEquals(text, ProgramPrinter.print(second.program()), "printing is stable");
    }

    @Test
    void theComparatorSeesADifference() {
        Program a = ScriptLoader.load(Examples.dir().resolve("hello-snake.xml"), Map.of()).program();
        Program b = ScriptLoader.load(Examples.dir().resolve("wheel.xml"), Map.of()).program();
        assertNotNull(ModelEquality.diff(a, b, "program"));
        String changed = ProgramPrinter.print(a).replace("angles=\"30\"", "angles=\"31\"");
        Program c = ScriptLoader.loadText(Path.of("x.xml"), changed, Map.of()).program();
        String d = ModelEquality.diff(a, c, "program");
        assertNotNull(d);
        assertTrue(d.contains("angles"), d);
    }
}
