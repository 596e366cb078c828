package org.parpe.gui.editor;

import org.parpe.gui.text.UiMsg;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.eclipse.jface.text.IDocument;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;

/**
 * Live validation: loads the editor text with the core's loader on a background thread a short
 * while after the last keystroke and hands the result to the UI thread. Results of texts that
 * have since changed are dropped, so the markers always describe the latest text. The pause
 * grows with the text (a quarter of a second, plus about 50 ms per megabyte, at most 2 s), so
 * that typing in a very large script does not start a load at every pause.
 */
public final class Validator implements AutoCloseable {
    private static final int DEBOUNCE_MS = 250;
    private static final int MAX_DEBOUNCE_MS = 2000;
    private static final int CHARS_PER_MS = 20_000;

    private final Display display;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "parpe-validate");
        t.setDaemon(true);
        return t;
    });
    private final AtomicLong generation = new AtomicLong();
    private final Consumer<NameIndex> names;

    /**
     * {@code names} receives, on the UI thread, the names of each program that loaded, and of
     * each text that did not load and is too large to scan at a keystroke.
     */
    public Validator(Display display, Consumer<NameIndex> names) {
        this.display = display;
        this.names = names;
    }

    /**
     * Validates the text of {@code document} (the content of {@code file}) soon; the text is
     * taken once, when the pause is over. {@code onResult} runs on the UI thread unless a newer
     * text was scheduled meanwhile. UI thread only.
     */
    public void schedule(Path file, IDocument document, Consumer<LoadResult> onResult) {
        long gen = generation.incrementAndGet();
        int delay = Math.min(MAX_DEBOUNCE_MS, DEBOUNCE_MS + document.getLength() / CHARS_PER_MS);
        display.timerExec(delay, () -> {
            if (gen != generation.get()) {
                return;
            }
            String text = document.get();
            worker.execute(() -> {
                if (gen != generation.get()) {
                    return;
                }
                LoadResult r = load(file, text, Map.of());
                NameIndex index = r.program() != null ? NameIndex.of(r.program())
                        : text.length() > ParslEditor.COLOUR_LIMIT ? NameIndex.of(text) : null;
                if (!display.isDisposed()) {
                    display.asyncExec(() -> {
                        if (gen == generation.get()) {
                            if (index != null) {
                                names.accept(index);
                            }
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
                    UiMsg.INTERNAL_ERROR_LOADING, e);
            return new LoadResult(null, List.of(d), List.of());
        }
    }

    @Override
    public void close() {
        generation.incrementAndGet();
        worker.shutdownNow();
    }
}
