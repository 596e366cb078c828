package org.parpe.serial.link;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;

/**
 * A test that drives a bus over a real pty pair made by socat: one pair per test, closed after
 * the host and emulator ends the test opened ({@link #openEnds()}, host first).
 */
public abstract class OverPty {
    @TempDir
    protected Path dir;
    protected PtyPair pty;

    @BeforeAll
    static void needSocat() {
        assumeTrue(PtyPair.available(), "socat is not installed (./test-all installs it)");
    }

    @BeforeEach
    void pair() throws Exception {
        pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"));
    }

    /** What the test opened on the pair, in the order to close it (null where nothing is open). */
    protected abstract AutoCloseable[] openEnds();

    @AfterEach
    void cleanUp() throws Exception {
        for (AutoCloseable end : openEnds()) {
            if (end != null) {
                end.close();
            }
        }
        if (pty != null) {
            pty.close();
        }
    }
}
