package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.InputStream;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;
import org.parpe.serial.link.PtyPair;

/**
 * The emulator's console reads the standard input the command line was handed, never the
 * process's own: run in-process by the tests, it read the forked JVM's standard input, where
 * Surefire sends its orders, and the fork waited 30 s at its end for an answer that never came.
 */
@Timeout(60)
class EmulatorInputTest {
    @TempDir
    Path dir;

    private InputStream before;
    private final AtomicInteger processInputReads = new AtomicInteger();

    @BeforeAll
    static void needSocat() {
        assumeTrue(PtyPair.available(), "socat is not installed (./test-all installs it)");
    }

    @BeforeEach
    void watchTheProcessInput() {
        before = System.in;
        System.setIn(new InputStream() {
            @Override
            public int read() {
                processInputReads.incrementAndGet();
                return -1;
            }

            @Override
            public int read(byte[] b, int off, int len) {
                processInputReads.incrementAndGet();
                return -1;
            }
        });
    }

    @AfterEach
    void restore() {
        System.setIn(before);
    }

    @Test
    void theConsoleAnswersTheLinesItWasHandedAndQuitEndsTheEmulator() throws Exception {
        try (PtyPair pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"))) {
            // 50 s: only "quit" on the handed input ends it within the test's minute
            Cli e = Cli.withInput("status\nquit\n", "emulate", "--protocol", "dxl2", "--model", "xm430-w210",
                    "--port", pty.b().toString(), "--modules", "1..2", "--duration", "50");
            assertEquals(0, e.code, e.toString());
            assertTrue(e.err.contains("servo 1: "), e.err);
            assertTrue(e.err.contains("servo 2: "), e.err);
            assertTrue(e.err.matches("(?s).*emulate: \\d+ packets accepted.*"), e.err);
            assertEquals(0, processInputReads.get(), "the console read the process's standard input");
        }
    }

    @Test
    void aRunWithNothingHandedNeverReadsTheProcessInput() throws Exception {
        try (PtyPair pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"))) {
            Cli e = Cli.run("emulate", "--protocol", "g1", "--port", pty.b().toString(), "--modules", "0..1",
                    "--duration", "0.3");
            assertEquals(0, e.code, e.toString());
            assertEquals(0, processInputReads.get(), "the console read the process's standard input");
        }
    }
}
