package org.parpe.sim.config;

import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.run.TargetException;
import org.parpe.sim.SimTarget;

/** Robot configurations from bad input: other scripts' digits, devices, FIFOs and huge files. */
class ConfigInputTest {
    @TempDir
    Path dir;

    private static String errors(String spec) {
        // read, generated and assembled as a run does it, so errors of every stage are found
        return org.junit.jupiter.api.Assertions.assertThrows(TargetException.class,
                () -> SimTarget.blueprint(spec, new int[] {0, 1})).diagnostics().toString();
    }

    @Test
    void nonAsciiDigitsAreNotNumbers() throws IOException {
        // Integer.parseInt reads "٣" (Arabic-Indic three) as 3; a generator argument must be 0-9
        assertTrue(errors("snake:n=\u0663").contains("n must be a whole number, got '\u0663'"));
        Path f = dir.resolve("arabic.xml");
        Files.writeString(f, "<robot-config>\n  <part name=\"s0\" type=\"segment\" id=\"0\" angle=\"\u0663\"/>\n"
                + "</robot-config>\n");
        String e = errors(f.toString());
        assertTrue(e.contains("arabic.xml:2:3: error: angle must be a number, got '\u0663'"), e);
    }

    @Test
    void devicesFifosAndHugeFilesAreRefused() throws Exception {
        assertTrue(errors("/dev/zero").contains("not a regular file"));
        Path fifo = dir.resolve("fifo.xml");
        new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor();
        // a FIFO without a writer would block the reader forever
        String e = assertTimeoutPreemptively(Duration.ofSeconds(20), () -> errors(fifo.toString()));
        assertTrue(e.contains("not a regular file"), e);
        Path big = dir.resolve("big.xml");
        Files.write(big, new byte[(16 << 20) + 1]);
        e = errors(big.toString());
        assertTrue(e.contains("larger than the limit of 16 MiB"), e);
    }
}
