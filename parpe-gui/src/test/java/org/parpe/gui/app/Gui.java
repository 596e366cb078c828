package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import org.parpe.gui.automation.Screenshot;
import org.parpe.gui.files.Examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.BooleanSupplier;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.ImageLoader;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;

/** What the GUI tests share: the display, bounded waits, examples and screenshots as evidence. */
public final class Gui {
    static final long WAIT_MS = 30_000;

    private Gui() {
    }

    /** The display; fails with a hint when there is no X server. */
    public static Display display() {
        String x = System.getenv("DISPLAY");
        if (x == null || x.isBlank()) {
            fail("No X display (DISPLAY is not set). The GUI tests need one: run them under xvfb-run, as ./test-all does.");
        }
        return Display.getDefault();
    }

    /** Runs the event loop until {@code done} holds; fails after {@link #WAIT_MS}. */
    static void pump(BooleanSupplier done, String what) {
        pump(done, what, WAIT_MS);
    }

    /** Runs the event loop until {@code done} holds; fails after {@code waitMs}. */
    public static void pump(BooleanSupplier done, String what, long waitMs) {
        Display display = Display.getDefault();
        long until = System.currentTimeMillis() + waitMs;
        while (!done.getAsBoolean()) {
            if (System.currentTimeMillis() > until) {
                fail("timed out after " + waitMs / 1000 + " s waiting for " + what);
            }
            if (!display.readAndDispatch()) {
                try {
                    Thread.sleep(5);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    fail("interrupted");
                }
            }
        }
    }

    /** Handles events for a moment, so that layouts and paints (GTK draws on its frame clock) are done. */
    public static void settle() {
        Display display = Display.getDefault();
        long until = System.currentTimeMillis() + 300;
        while (System.currentTimeMillis() < until) {
            if (!display.readAndDispatch()) {
                display.update();
                try {
                    Thread.sleep(5);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    fail("interrupted");
                }
            }
        }
    }

    /** Stops the run if any and waits until its end has been reported to the window (through asyncExec). */
    static void endRun(IdeWindow ide) {
        boolean started = ide.runs.running() || ide.runs.controller().status() != null;
        ide.runs.stop();
        pump(() -> !ide.runs.running() && (!started || ide.runs.lastOutcome() != null), "the run to end");
    }

    /** Opens {@code file} in {@code ide} and waits until it is in the editor (files are read in the background). */
    public static void open(IdeWindow ide, Path file) {
        Path abs = file.toAbsolutePath().normalize();
        ide.files.openPath(abs);
        pump(() -> !ide.files.reading() && abs.equals(ide.files.file()), "opening " + file.getFileName());
    }

    public static Path example(String name) {
        Path p = Examples.folder() == null ? null : Examples.folder().resolve(name);
        assertTrue(p != null && Files.isRegularFile(p), "example " + name + " not found (parpe.examples=" + System.getProperty("parpe.examples") + ")");
        return p;
    }

    /** Saves a screenshot of {@code shell} under the artefacts folder and checks it is not blank. */
    public static void screenshot(Shell shell, String name) throws Exception {
        Path dir = Path.of(System.getProperty("parpe.artefacts", "target/gui-test-artefacts"));
        Files.createDirectories(dir);
        Path f = dir.resolve(name);
        Screenshot.save(shell, f);
        ImageData d = new ImageLoader().load(f.toString())[0];
        assertTrue(d.width > 600 && d.height > 400, "screenshot too small: " + d.width + "x" + d.height);
        assertTrue(Screenshot.distinctColours(d, 64) >= 64, "screenshot " + f + " looks blank");
    }

    /** A new IDE window, automated (no recovery offered), with its settings in {@code home}, after its first validation. */
    public static IdeWindow openIde(Path home) {
        IdeWindow ide = new IdeWindow(display(), new Prefs(home));
        ide.open(null, true);
        pump(() -> ide.validations() > 0, "the first validation");
        return ide;
    }

    /** As {@link #openIde(Path)}, in a window of {@code width} × {@code height} pixels at the screen's corner. */
    public static IdeWindow openIde(Path home, int width, int height) {
        IdeWindow ide = openIde(home);
        ide.shell.setBounds(0, 0, width, height);
        settle();
        return ide;
    }

    /** Ends any run of {@code ide} and closes its window (for {@code @AfterAll}). */
    public static void closeIde(IdeWindow ide) {
        if (ide != null && !ide.shell.isDisposed()) {
            endRun(ide);
            ide.shell.dispose();
        }
    }

    /**
     * Runs xdotool, which moves and presses the pointer through the X server (XTest), so that
     * GTK makes the double and triple clicks from the real events' times as it does for a user.
     * SWT's Display.post cannot: on GTK 3 it queues one synthetic event with time 0.
     */
    public static void xdotool(String... args) {
        java.util.List<String> cmd = new java.util.ArrayList<>(java.util.List.of("xdotool"));
        cmd.addAll(java.util.List.of(args));
        try {
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
            assertTrue(p.waitFor(20, java.util.concurrent.TimeUnit.SECONDS), "xdotool did not finish");
            assertEquals(0, p.exitValue(), "xdotool " + String.join(" ", args) + " failed: " + out);
        } catch (java.io.IOException e) {
            throw new AssertionError("these tests need xdotool (apt-get install xdotool; ./test-all installs it): " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError("interrupted", e);
        }
    }
}
