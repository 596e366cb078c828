package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;

/**
 * What file and folder names and long texts can do to the generated C: nothing. A name that
 * ends a comment ({@code *\} and a line break, then {@code /}, or the trigraph {@code ??/})
 * or starts a new line in the {@code .ino}'s first line must not splice code into the program,
 * and a text longer than C99's 4 095-character string limit must compile under
 * {@code -pedantic -Werror}. Both compile the exported C with gcc and would fail with the
 * injected {@code #error}.
 */
class ExportNamesTest {
    @TempDir
    Path tmp;

    @BeforeAll
    static void compilerInstalled() {
        HostCompiler.require("gcc");
    }

    @Test
    void fileAndFolderNamesCannotInjectCode() throws Exception {
        Path folder = Files.createDirectories(tmp.resolve("a*\\\n/\n#error spliced through a folder\n/* ??/"));
        Path script = folder.resolve("x\n#error injected through a file name\n.xml");
        Files.copy(ExportEqualityTest.ROOT.resolve("examples/hello-snake.xml"), script);
        Path out = tmp.resolve("c");
        Cli export = Cli.run(List.of("export", script.toString(), "--target", "c", "--out", out.toString()));
        assertEquals(0, export.code, () -> "export: " + export);
        HostCompiler.compile(out);
        for (String f : List.of("parsl_program.c", "parsl_program.h")) {
            for (String line : Files.readAllLines(out.resolve(f))) {
                assertFalse(line.startsWith("#error") || line.startsWith("/") && !line.startsWith("/*"), f + ": " + line);
                if (line.startsWith("/*")) {
                    assertTrue(line.matches("/\\*[ -~&&[^\\\\?]]*"), () -> f + ": a comment with more than printable"
                            + " ASCII without \\ and ?: " + line);
                }
            }
        }
        Cli sketch = Cli.run(List.of("export", script.toString(), "--target", "arduino", "--out", tmp.resolve("s").toString()));
        assertEquals(0, sketch.code, () -> "export: " + sketch);
        Path ino;
        try (var s = Files.list(tmp.resolve("s"))) {
            Path dir = s.findFirst().orElseThrow();
            ino = dir.resolve(dir.getFileName() + ".ino");
        }
        String first = Files.readAllLines(ino).get(0);
        assertTrue(first.startsWith(org.parpe.serial.export.ProgramExport.MARK) && first.contains("x_#error injected through a file name_.xml"),
                first);
        assertFalse(Files.readString(ino).lines().anyMatch(l -> l.startsWith("#error")), "no line of the name in the .ino");
    }

    /** The host program names a script in a non-ASCII folder as parpe run does (UTF-8, not one byte per char). */
    @Test
    void nonAsciiPathsAreWrittenAsParpeRunWritesThem() throws Exception {
        Path script = Files.createDirectories(tmp.resolve("schlange-ä-蛇")).resolve("divide-by-zero.xml");
        Files.copy(Path.of("src/test/resources/export/divide-by-zero.xml"), script);
        Cli run = Cli.run(List.of("run", script.toString(), "--duration", "3", "--trace", tmp.resolve("j.csv").toString()));
        assertEquals(3, run.code, () -> "run: " + run);
        Path out = tmp.resolve("c");
        Cli export = Cli.run(List.of("export", script.toString(), "--target", "c", "--out", out.toString()));
        assertEquals(0, export.code, () -> "export: " + export);
        HostCompiler.compile(out);
        HostCompiler.Result r = HostCompiler.run(out, List.of("./program", "--duration", "3", "--trace",
                tmp.resolve("c.csv").toString()), 60);
        assertEquals(3, r.code(), r.err());
        String place = run.err.lines().filter(l -> l.contains(": error: ")).findFirst().orElseThrow();
        assertTrue(r.err().startsWith(place.substring(0, place.indexOf(": error: "))), () -> r.err() + " vs " + place);
    }

    @Test
    void textsLongerThanACStringLiteralCompileUnderPedantic() throws Exception {
        StringBuilder sum = new StringBuilder("0");
        while (sum.length() < 5000) {
            sum.append(" + 0");
        }
        Path script = tmp.resolve("long.xml");
        Files.writeString(script, "<program><robot><structure><body elements=\"0\"/></structure></robot>\n"
                + "<main><go/></main><behaviors><go><wave group=\"body\"/></go></behaviors>\n"
                + "<automata><wave states=\"up, down\"/></automata>\n"
                + "<states><up angles=\"" + sum + " + 30*sin($time)\"/><down angles=\"-30\"/></states></program>\n");
        Path out = tmp.resolve("c");
        Cli export = Cli.run(List.of("export", script.toString(), "--target", "c", "--out", out.toString()));
        assertEquals(0, export.code, () -> "export: " + export);
        List<String> cmd = new ArrayList<>(List.of("gcc", "-std=c99", "-pedantic", "-Wall", "-Werror", "-Woverlength-strings",
                "-O0", "-o", "program"));
        try (var s = Files.list(out)) {
            s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".c")).sorted().forEach(cmd::add);
        }
        cmd.add("-lm");
        HostCompiler.Result r = HostCompiler.run(out, cmd, 300);
        assertEquals(0, r.code(), () -> "gcc -pedantic:\n" + r.err());
        HostCompiler.Result run = HostCompiler.run(out, List.of("./program", "--duration", "0.05", "--trace", "-"), 60);
        assertEquals(0, run.code(), run.err());
    }
}
