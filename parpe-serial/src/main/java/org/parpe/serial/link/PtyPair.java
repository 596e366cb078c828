package org.parpe.serial.link;

import org.parpe.serial.text.SerialMsg;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * A pair of connected pseudo-terminals made by {@code socat}, like two serial ports joined by a
 * null-modem cable: what is written to {@link #a()} is read from {@link #b()} and back. Used by
 * the tests and the benchmark to run the driver and the emulator over real serial devices.
 * {@link #close()} kills socat, which makes both devices disappear, as unplugging would.
 */
public final class PtyPair implements AutoCloseable {
    private static final long START_TIMEOUT_MS = 5000;

    private final Path a;
    private final Path b;
    private final Thread reaper = new Thread(this::unplug, "pty-pair-reaper");
    private volatile Process socat;

    private PtyPair(Path a, Path b) {
        this.a = a;
        this.b = b;
    }

    /** Starts socat with the two devices linked at {@code a} and {@code b}. */
    public static PtyPair start(Path a, Path b) throws IOException {
        PtyPair p = new PtyPair(a, b);
        // socat outlives the JVM unless killed: make sure an aborted test run does not leave it behind.
        Runtime.getRuntime().addShutdownHook(p.reaper);
        try {
            p.restart();
        } catch (IOException | RuntimeException e) {
            p.close();
            throw e;
        }
        return p;
    }

    /** Whether socat can be run. */
    public static boolean available() {
        try {
            Process p = new ProcessBuilder("socat", "-V").redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            return p.waitFor(5, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    /** The first device. */
    public Path a() {
        return a;
    }

    /** The second device. */
    public Path b() {
        return b;
    }

    /** (Re)starts socat after {@link #unplug()}: the devices come back at the same paths. */
    public void restart() throws IOException {
        if (socat != null && socat.isAlive()) {
            return;
        }
        Files.deleteIfExists(a);
        Files.deleteIfExists(b);
        try {
            socat = new ProcessBuilder("socat", "pty,raw,echo=0,link=" + a, "pty,raw,echo=0,link=" + b)
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        } catch (IOException e) {
            throw new IOException(SerialMsg.SOCAT_MISSING.text(e.getMessage()), e);
        }
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(START_TIMEOUT_MS);
        while (!(Files.exists(a) && Files.exists(b))) {
            if (!socat.isAlive() || System.nanoTime() > deadline) {
                unplug();
                throw new IOException(SerialMsg.SOCAT_NO_PTYS.text(a, b));
            }
            try {
                Thread.sleep(10);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException(SerialMsg.SOCAT_INTERRUPTED.text(), e);
            }
        }
    }

    /** Kills socat: both devices disappear. */
    public void unplug() {
        Process p = socat;
        if (p == null) {
            return;
        }
        p.destroy();
        try {
            if (!p.waitFor(2, TimeUnit.SECONDS)) {
                p.destroyForcibly().waitFor(2, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            p.destroyForcibly();
        }
        socat = null;
    }

    @Override
    public void close() {
        unplug();
        try {
            Runtime.getRuntime().removeShutdownHook(reaper);
        } catch (IllegalStateException | IllegalArgumentException e) {
            // The JVM is shutting down (the hook runs now) or the hook was removed already.
        }
        try {
            Files.deleteIfExists(a);
            Files.deleteIfExists(b);
        } catch (IOException e) {
            // socat removes its links itself; a leftover is harmless.
        }
    }
}
