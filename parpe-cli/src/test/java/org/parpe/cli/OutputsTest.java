package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.BadInputTest.Result;
import org.parpe.cli.options.OutputFile;
import org.parpe.cli.options.UsageException;

/**
 * Outputs (trace, metrics, plot, recording) go through {@link OutputFile}: devices, directories,
 * FIFOs and the run's own inputs are refused before the run, a failed write exits 2, and what
 * was at the target is replaced whole or not at all.
 */
class OutputsTest {
    @TempDir
    Path dir;

    private static Result parpe(String... args) {
        return BadInputTest.parpe(args);
    }

    private Path script() throws IOException {
        Path p = dir.resolve("x.xml");
        Files.writeString(p, CliContractTest.GOOD);
        return p;
    }

    @Test
    void aFullDeviceOrAMissingDirectoryIsAUsageError() throws Exception {
        String x = script().toString();
        Result full = parpe("run", x, "--duration", "0.5", "--trace", "/dev/full");
        assertEquals(2, full.code(), full.err());
        assertTrue(full.err().contains("cannot write --trace file '/dev/full': it is not a regular file"), full.err());
        Result missing = parpe("run", x, "--duration", "0.5", "--trace", x + "/t.csv");
        assertEquals(2, missing.code(), missing.err());
        assertTrue(missing.err().contains("cannot write --trace file '" + x + "/t.csv': directory"), missing.err());
        Result metrics = parpe("run", x, "--sim", "--duration", "0.1", "--metrics", dir.resolve("no/m.json").toString());
        assertEquals(2, metrics.code(), metrics.err());
        assertTrue(metrics.err().contains("cannot write --metrics file"), metrics.err());
    }

    @Test
    void inputsDirectoriesAndFifosAreNeverReplaced() throws Exception {
        Path x = script();
        Path stim = dir.resolve("s.txt");
        Files.writeString(stim, "0.5 $dir=down\n");
        for (String target : List.of(x.toString(), dir.resolve(".").resolve("x.xml").toString(), stim.toString())) {
            Result r = parpe("run", x.toString(), "--duration", "0.5", "--stimulus", stim.toString(), "--trace", target);
            assertEquals(2, r.code(), r.err());
            assertTrue(r.err().contains("it is the input file"), r.err());
        }
        assertEquals(CliContractTest.GOOD, Files.readString(x));
        Path empty = Files.createDirectory(dir.resolve("empty"));
        Path fifo = dir.resolve("fifo.png");
        new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor();
        for (Path target : List.of(empty, fifo)) {
            Result r = parpe("run", x.toString(), "--sim", "--duration", "0.1", "--plot", target.toString());
            assertEquals(2, r.code(), r.err());
            assertTrue(Files.exists(target), target + " was deleted");
        }
        Path inc = dir.resolve("inc.xml");
        Files.writeString(inc, "<lib/>\n");
        Path withInclude = dir.resolve("main.xml");
        Files.writeString(withInclude, CliContractTest.GOOD.replace("</program>", "<include file=\"inc.xml\"/></program>"));
        Result r = parpe("run", withInclude.toString(), "--duration", "0.5", "--trace", inc.toString());
        assertEquals(2, r.code(), r.err());
        assertEquals("<lib/>\n", Files.readString(inc));
    }

    @Test
    void aFailedWriteLeavesTheOldFileAndNoTemporaryFile() throws Exception {
        Path target = dir.resolve("m.json");
        Files.writeString(target, "old");
        OutputFile f = OutputFile.of(OutputFile.plan(List.of()), "--metrics", target.toString());
        UsageException e = assertThrows(UsageException.class, () -> f.write(out -> {
            out.write("half".getBytes());
            throw new IOException("No space left on device");
        }));
        assertEquals("cannot write --metrics file '" + target + "': No space left on device", e.getMessage());
        assertEquals("old", Files.readString(target));
        f.write("new");
        assertEquals("new", Files.readString(target));
        try (var files = Files.list(dir)) {
            assertEquals(List.of(target), files.toList());
        }
    }

    @Test
    void recordRefusesReservedGroupNamesAndBadTargetsBeforeRecording() throws Exception {
        String out = dir.resolve("rec.xml").toString();
        Result sin = parpe("record", "--port", dir.resolve("no-port").toString(), "--group", "sin", "--modules", "0..1",
                "--out", out);
        assertEquals(2, sin.code(), sin.err());
        assertTrue(sin.err().contains("--group 'sin' cannot be used: 'sin' is a reserved word"), sin.err());
        Result toDir = parpe("record", "--port", dir.resolve("no-port").toString(), "--group", "arm", "--modules", "0..1",
                "--out", dir.toString());
        assertEquals(2, toDir.code(), toDir.err());
        assertTrue(toDir.err().contains("cannot write --out file '" + dir + "': it is a directory"), toDir.err());
    }
}
