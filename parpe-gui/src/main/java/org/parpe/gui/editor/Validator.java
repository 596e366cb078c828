package org.parpe.gui.editor;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;

/**
 * Live validation: loads the editor text with the core's loader on a background thread a short
 * while after the last keystroke and hands the result to the UI thread. Results of texts that
 * have since changed are dropped, so the markers always describe the latest text.
 */
public final class Validator implements AutoCloseable {
    private static final int DEBOUNCE_MS = 250;

    private final Display display;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "parpe-validate");
        t.setDaemon(true);
        return t;
    });
    private final AtomicLong generation = new AtomicLong();

    public Validator(Display display) {
        this.display = display;
    }

    /**
     * Validates {@code text} (the content of {@code file}) soon; {@code onResult} runs on the UI
     * thread unless a newer text was scheduled meanwhile. UI thread only.
     */
    public void schedule(Path file, String text, Consumer<LoadResult> onResult) {
        long gen = generation.incrementAndGet();
        display.timerExec(DEBOUNCE_MS, () -> {
            if (gen != generation.get()) {
                return;
            }
            worker.execute(() -> {
                if (gen != generation.get()) {
                    return;
                }
                LoadResult r = load(file, text, Map.of());
                if (!display.isDisposed()) {
                    display.asyncExec(() -> {
                        if (gen == generation.get()) {
                            onResult.accept(r);
                        }
                    });
                }
            });
        });
    }

    /**
     * Loads {@code text} now, on the calling thread. Never throws: an internal failure of the
     * loader becomes one error diagnostic.
     */
    public static LoadResult load(Path file, String text, Map<String, Double> params) {
        try {
            return ScriptLoader.loadText(file, text, params);
        } catch (RuntimeException | StackOverflowError e) {
            Diagnostic d = new Diagnostic(Severity.ERROR, new SourcePos(file.toString(), 1, 1),
                    "internal error while loading (please report it): " + e);
            return new LoadResult(null, List.of(d), List.of());
        }
    }

    @Override
    public void close() {
        generation.incrementAndGet();
        worker.shutdownNow();
    }
}
