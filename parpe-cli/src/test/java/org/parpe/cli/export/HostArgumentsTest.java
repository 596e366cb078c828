package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;

/**
 * The exported host program refuses the arguments and stimulus files that {@code parpe run}
 * refuses (exit 2), with the place of a bad stimulus line counted as parpe run counts it, also
 * after a line longer than the program's line buffer.
 */
class HostArgumentsTest {
    static final Path SCRIPT = ExportEqualityTest.ROOT.resolve("examples/teleop-dirwave.xml");

    @TempDir
    static Path tmp;
    static Path program;

    @BeforeAll
    static void export() throws Exception {
        HostCompiler.require("gcc");
        Cli export = Cli.run(List.of("export", SCRIPT.toString(), "--out", tmp.resolve("c").toString()));
        assertEquals(0, export.code, () -> "export: " + export);
        program = HostCompiler.compile(tmp.resolve("c"));
    }

    @Test
    void durationsAndSeedsThatParpeRunRefuses() throws Exception {
        for (List<String> args : List.of(List.of("--duration", "abc"), List.of("--duration", "-1"),
                List.of("--duration", "0x10"), List.of("--duration", "1e400"), List.of("--duration", "inf"),
                List.of("--duration", "1e8"), List.of("--seed", "x"), List.of("--seed", "1.5"))) {
            Cli run = Cli.run(List.of("run", SCRIPT.toString(), args.get(0), args.get(1), "--duration".equals(args.get(0))
                    ? "--seed" : "--duration", "1"));
            assertEquals(2, run.code, () -> args + ": parpe run " + run);
            HostCompiler.Result r = HostCompiler.run(tmp, List.of(program.toString(), args.get(0), args.get(1)), 30);
            assertEquals(2, r.code(), () -> args + ": the exported program accepts it: " + r.err());
        }
        HostCompiler.Result ok = HostCompiler.run(tmp, List.of(program.toString(), "--duration", "0.05", "--seed", "-3"), 30);
        assertEquals(0, ok.code(), ok.err());
    }

    @Test
    void stimulusTimesThatParpeRunRefusesAndLongLines() throws Exception {
        String pad = "#" + "x".repeat(600) + "\n";
        for (String time : List.of("0x1p-4", "inf", "0x10", "nan", "1e400", "1s")) {
            Path stim = tmp.resolve("s.stim");
            Files.writeString(stim, pad + "0.1 $speed=1\n" + time + " $speed=1\n");
            Cli run = Cli.run(List.of("run", SCRIPT.toString(), "--duration", "1", "--stimulus", stim.toString()));
            assertEquals(2, run.code, () -> time + ": parpe run " + run);
            HostCompiler.Result r = HostCompiler.run(tmp, List.of(program.toString(), "--duration", "1", "--stimulus",
                    stim.toString()), 30);
            assertEquals(2, r.code(), () -> time + ": the exported program accepts it: " + r.err());
            assertTrue(r.err().startsWith(stim + ":3:1: error: ") && run.err.contains(stim + ":3:1: error: "),
                    () -> time + ": line 3 (after a 601-character line):\n" + r.err() + "\nparpe run:\n" + run.err);
        }
    }
}
