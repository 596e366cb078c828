package org.parpe.gui.editor;

import org.parpe.gui.text.UiMsg;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.eclipse.jface.text.DocumentEvent;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IDocumentListener;
import org.eclipse.swt.SWTException;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ParsedScript;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;

/**
 * The open script: the editor's text, one version per change, read by the core's loader once
 * per version on one worker thread (never the UI thread). Every view that needs the script
 * (Problems, the outline, the diagram and its palette, a run, the sweep) reads it here, so an
 * edit costs one load however many views are open. Listeners hear of each checked version on
 * the UI thread a short while after the last keystroke (a quarter of a second, plus about 50 ms
 * per megabyte, at most 2 s, so that typing in a very large script does not start a load at
 * every pause); results of texts that have since changed are never handed on. A view that needs
 * the text sooner asks with {@link #whenLoaded}, an action that needs it now with
 * {@link #loaded}. Loading with parameter values binds the version read ({@link Loaded#bind}).
 * UI thread only, except {@link #load}.
 */
public final class ScriptDocument implements AutoCloseable {
    private static final int DEBOUNCE_MS = 250;
    private static final int MAX_DEBOUNCE_MS = 2000;
    private static final int CHARS_PER_MS = 20_000;

    /**
     * One version of the text, loaded.
     *
     * @param version the version of the text ({@link ScriptDocument#version})
     * @param file    the path it was loaded as (includes and the robot file are found next to it)
     * @param text    the text
     * @param parsed  the text as read with its includes and robot file, or {@code null} when the
     *                loader failed
     * @param result  the text loaded with its parameters' defaults
     * @param names   the names it defines, for completion, or {@code null} (a text that did not
     *                load and is small enough to scan at a keystroke)
     */
    public record Loaded(long version, Path file, String text, ParsedScript parsed, LoadResult result, NameIndex names) {
        /** The program, or {@code null} when the text does not load. */
        public Program program() {
            return result.program();
        }

        /**
         * This version loaded with parameter values {@code params} (defaults for the others),
         * without reading a file again. Never throws.
         */
        public LoadResult bind(Map<String, Double> params) {
            return params.isEmpty() || parsed == null ? result
                    : guarded(file, () -> ScriptLoader.bind(parsed, params));
        }
    }

    private final Display display;
    private final IDocument document;
    private final Supplier<Path> file;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "parpe-load");
        t.setDaemon(true);
        return t;
    });
    private final AtomicLong version = new AtomicLong();
    private final AtomicInteger loads = new AtomicInteger();
    private final List<Consumer<Loaded>> listeners = new ArrayList<>();
    private final List<Consumer<Loaded>> waiting = new ArrayList<>();
    private Loaded last;
    private Future<Loaded> pending;
    private long pendingVersion = -1;
    private Path pendingFile;
    private long checks;
    private boolean listenersDue;

    /** The document of {@code document}, the text of the file {@code file} names (it changes at Save As). */
    public ScriptDocument(Display display, IDocument document, Supplier<Path> file) {
        this.display = display;
        this.document = document;
        this.file = file;
        document.addDocumentListener(new IDocumentListener() {
            @Override
            public void documentAboutToBeChanged(DocumentEvent event) {
            }

            @Override
            public void documentChanged(DocumentEvent event) {
                version.incrementAndGet();
                check();
            }
        });
    }

    /** The editor's document (edits through it are undoable). */
    public IDocument document() {
        return document;
    }

    /** The text now. */
    public String text() {
        return document.get();
    }

    /** The path the text is loaded as. */
    public Path file() {
        return file.get();
    }

    /** The version of the text now: it grows at each change. */
    public long version() {
        return version.get();
    }

    /** {@code listener} hears of each version checked, on the UI thread. */
    public void addListener(Consumer<Loaded> listener) {
        listeners.add(listener);
    }

    /**
     * Tells the listeners of the text soon, after the pause a keystroke waits for (the text or
     * its file changed); the text is taken once, when the pause is over.
     */
    public void check() {
        long gen = ++checks;
        int delay = Math.min(MAX_DEBOUNCE_MS, DEBOUNCE_MS + document.getLength() / CHARS_PER_MS);
        display.timerExec(delay, () -> {
            if (gen == checks && !worker.isShutdown()) {
                listenersDue = true;
                delivered(null); // at once if the version is loaded already (a view asked for it), else once it is
            }
        });
    }

    /** The version now, loaded, or {@code null} when it has not been read yet. */
    public Loaded current() {
        Loaded l = last;
        return l != null && l.version() == version.get() && l.file().equals(file.get()) ? l : null;
    }

    /**
     * Calls {@code then} with the version now once it is loaded: at once when it is, otherwise on
     * the UI thread when the worker has read it (or a newer one, if the text changes meanwhile).
     */
    public void whenLoaded(Consumer<Loaded> then) {
        Loaded now = current();
        if (now != null) {
            then.accept(now);
            return;
        }
        waiting.add(then);
        request();
    }

    /** The version now, loaded: waits for the worker when it has not read it yet. */
    public Loaded loaded() {
        Loaded now = current();
        if (now != null) {
            return now;
        }
        request();
        Loaded l = waitFor(pending);
        if (l == null) { // the window is closing: nobody is left to wait for
            l = read(version.get(), file.get(), document.get());
        }
        keep(l);
        return l;
    }

    /**
     * Reads the text again as a new version, for an action that must see the files it includes
     * as they are now (Run), and returns it loaded.
     */
    public Loaded reread() {
        version.incrementAndGet();
        return loaded();
    }

    /** How many times the text was read (tests count them per edit). */
    public int loads() {
        return loads.get();
    }

    /** Whether a read of the text is waiting for the worker or going on. */
    public boolean busy() {
        return pending != null && !pending.isDone();
    }

    private void request() {
        long v = version.get();
        Path f = file.get();
        if (pending != null && pendingVersion == v && f.equals(pendingFile)) {
            return;
        }
        String text = document.get();
        pendingVersion = v;
        pendingFile = f;
        try {
            pending = worker.submit(() -> v != version.get() ? null : read(v, f, text));
        } catch (RejectedExecutionException closed) {
            pending = null;
        }
    }

    private Loaded read(long v, Path f, String text) {
        ParsedScript parsed = null;
        LoadResult r;
        try {
            parsed = ScriptLoader.read(f, text);
            r = ScriptLoader.bind(parsed, Map.of());
        } catch (RuntimeException | StackOverflowError e) {
            r = failed(f, e);
        }
        NameIndex names = r.program() != null ? NameIndex.of(r.program())
                : text.length() > ParslEditor.COLOUR_LIMIT ? NameIndex.of(text) : null;
        loads.incrementAndGet();
        Loaded l = new Loaded(v, f, text, parsed, r, names);
        if (!display.isDisposed()) {
            try {
                display.asyncExec(() -> delivered(l));
            } catch (SWTException gone) {
                // the display was disposed meanwhile: nobody is left to tell
            }
        }
        return l;
    }

    private void keep(Loaded l) {
        if (l != null && (last == null || l.version() >= last.version())) {
            last = l;
        }
    }

    private void delivered(Loaded l) {
        if (worker.isShutdown()) {
            return; // the window closed while the text was read: nobody is left to tell
        }
        keep(l);
        Loaded now = current();
        if (now == null) {
            if (listenersDue || !waiting.isEmpty()) {
                request();
            }
            return;
        }
        List<Consumer<Loaded>> then = List.copyOf(waiting);
        waiting.clear();
        then.forEach(c -> c.accept(now));
        if (listenersDue) {
            listenersDue = false;
            listeners.forEach(c -> c.accept(now));
        }
    }

    private static Loaded waitFor(Future<Loaded> f) {
        if (f == null) {
            return null;
        }
        try {
            return f.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        } catch (ExecutionException | CancellationException e) {
            return null;
        }
    }

    /**
     * Loads {@code text} (not the editor's: a file of its own, or a program the IDE made) now, on
     * the calling thread, as the document loads its text. Never throws: an internal failure of
     * the loader becomes one error diagnostic.
     */
    public static LoadResult load(Path file, String text, Map<String, Double> params) {
        return guarded(file, () -> ScriptLoader.loadText(file, text, params));
    }

    private static LoadResult guarded(Path file, Supplier<LoadResult> loading) {
        try {
            return loading.get();
        } catch (RuntimeException | StackOverflowError e) {
            return failed(file, e);
        }
    }

    /** An internal failure of the loader, as the one error of the text. */
    private static LoadResult failed(Path file, Throwable e) {
        Diagnostic d = new Diagnostic(Severity.ERROR, new SourcePos(file.toString(), 1, 1), UiMsg.INTERNAL_ERROR_LOADING, e);
        return new LoadResult(null, List.of(d), List.of());
    }

    @Override
    public void close() {
        checks++;
        worker.shutdownNow();
    }
}
