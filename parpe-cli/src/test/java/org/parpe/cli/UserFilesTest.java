package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 31 item 5: the outputs and inputs users hit in the fault and bad-input campaigns. */
class UserFilesTest {
    @TempDir
    Path dir;

    /** {@code chmod 444 t.csv; parpe run … --trace t.csv} replaced the file (the CI runs as root, who may write it). */
    @Test
    void aWriteProtectedOutputIsRefusedAndKept() throws Exception {
        Path x = Files.writeString(dir.resolve("x.xml"), CliContractTest.GOOD);
        Path t = Files.writeString(dir.resolve("t.csv"), "mine\n");
        Files.setPosixFilePermissions(t, PosixFilePermissions.fromString("r--r--r--"));
        Cli r = Cli.run("run", x.toString(), "--duration", "0.1", "--trace", t.toString());
        assertEquals(2, r.code, r.toString());
        assertEquals("parpe: cannot write --trace file '" + t + "': it is write-protected; make it writable (chmod u+w)"
                + " or choose another name\n", r.err);
        assertEquals("mine\n", Files.readString(t));
        assertEquals("r--r--r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(t)));
    }

    /** A script with a 251-byte name: its sketch's {@code .ino} has 251 bytes, its temporary name had 273. */
    @Test
    void theSketchOfAScriptWithTheLongestNameIsWritten() throws Exception {
        Path script = dir.resolve("s".repeat(247) + ".xml");
        Files.copy(Path.of("..", "examples", "hello-snake.xml"), script);
        Path out = dir.resolve("out");
        Cli r = Cli.run(List.of("export", script.toString(), "--target", "arduino", "--out", out.toString()));
        assertEquals(0, r.code, r.toString());
        Path ino = out.resolve("s".repeat(247)).resolve("s".repeat(247) + ".ino");
        assertTrue(Files.readString(ino).contains("setup"), ino.toString());
    }
}
