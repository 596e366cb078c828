package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.cli.Cli;

/**
 * The two forms of the exported program's tick agree bit for bit (issue 36 item 3): the common
 * case generated per automaton ({@code PARSL_FAST}) and the runtime's general {@code
 * parsl_advance} alone ({@code -DPARSL_NO_FAST}). For every script of {@link ExportEqualityTest}
 * (which compares the first with the interpreter) both builds run the same ticks with the same
 * seed; after every tick a hash of the bits of every setpoint, every module's state and the
 * expression context must be equal, and so must how the run ended (the error, its place and its
 * operands).
 */
class FastFormTest {
    @TempDir
    Path tmp;

    @BeforeAll
    static void compilerInstalled() {
        HostCompiler.require("gcc");
    }

    static List<ExportEqualityTest.Case> cases() throws Exception {
        return ExportEqualityTest.cases().stream().filter(c -> !c.check()).toList();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void bothFormsGiveTheSameBits(ExportEqualityTest.Case c) throws Exception {
        List<String> export = new ArrayList<>(List.of("export", c.script().toString(), "--target", "c", "--out",
                tmp.toString()));
        export.addAll(ExportEqualityTest.options(c.runArgs(), "--tick", "--param"));
        assertEquals(0, Cli.run(export).code, "export");
        assertEquals(run(tmp, "general", "-DPARSL_NO_FAST"), run(tmp, "fast"), "hashes of the ticks");
    }

    @Test
    void theBenchmarkSnakeRunsTheCommonCase() throws Exception {
        Path script = tmp.resolve("snake.xml");
        Files.writeString(script, org.parpe.cli.bench.CoreBenchmark.snake(40));
        assertEquals(0, Cli.run("export", script.toString(), "--target", "c", "--out", tmp.toString()).code);
        assertTrue(Files.readString(tmp.resolve("parsl_program.c")).contains("case 0: fast0(r, v); return 1;"),
                "the snake's automaton has the common case");
        String fast = run(tmp, "fast");
        assertEquals(run(tmp, "general", "-DPARSL_NO_FAST"), fast);
        assertTrue(fast.contains("end 1 error 0"), fast.lines().reduce((a, b) -> b).orElse(""));
    }

    /** The driver's output of 300 ticks with seed 7, built with {@code flags}. */
    private static String run(Path dir, String name, String... flags) throws Exception {
        Files.deleteIfExists(dir.resolve("parsl_host.c"));
        Files.copy(Path.of("src/test/resources/export/forms.c"), dir.resolve("forms.c"),
                java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        Path program = HostCompiler.compile(dir, name, flags);
        HostCompiler.Result r = HostCompiler.run(dir, List.of(program.toString(), "300", "7"), 60);
        assertEquals(0, r.code(), r.err());
        return r.out();
    }
}
