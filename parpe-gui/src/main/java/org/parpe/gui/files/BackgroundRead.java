package org.parpe.gui.files;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.BiConsumer;
import org.eclipse.swt.widgets.Display;

/**
 * Reads a script on a background thread, so that opening a large one never freezes the window,
 * and hands its text to the UI thread. A later read, or {@link #cancel}, wins over one still
 * being read: its result is dropped. UI thread only, but for the reading itself.
 */
final class BackgroundRead {
    private final Display display;
    private final ExecutorService reader = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "parpe-open");
        t.setDaemon(true);
        return t;
    });
    /** The number of the read whose result counts. */
    private long current;
    private boolean busy;

    BackgroundRead(Display display) {
        this.display = display;
    }

    /**
     * Reads {@code file}; then, on the UI thread, {@code done} gets its text and null, or null and
     * why it could not be read, unless another read or a cancel came since.
     */
    void read(Path file, BiConsumer<String, String> done) {
        long number = ++current;
        busy = true;
        reader.execute(() -> {
            String text = null;
            String error = null;
            try {
                text = Files.readString(file, StandardCharsets.UTF_8);
            } catch (IOException | RuntimeException e) {
                error = org.parpe.core.io.IoReasons.of(e);
            }
            String t = text;
            String why = error;
            try {
                display.asyncExec(() -> {
                    if (number == current) {
                        busy = false;
                        done.accept(t, why);
                    }
                });
            } catch (org.eclipse.swt.SWTException e) {
                // The window closed while the file was read.
            }
        });
    }

    /** Drops the result of the read under way, if any. */
    void cancel() {
        current++;
        busy = false;
    }

    /** Whether a file is being read. */
    boolean busy() {
        return busy;
    }

    /** Stops the reading thread (the window closes). */
    void close() {
        reader.shutdownNow();
    }
}
