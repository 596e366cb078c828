package org.parpe.gui.diagram;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicLong;
import org.parpe.core.diagram.Layouts;
import org.parpe.core.diagram.NodePlaces;
import org.parpe.core.model.Program;
import org.parpe.gui.diagram.Projection.View;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.gui.panels.Zoom;

/**
 * The layout of the Diagram pane: the editor's text projected on a worker ({@link Projection};
 * the newest request wins), then, on the UI thread, the ring or the wheel laid out again with
 * text large enough to read on the canvas as it is now. Each layout carries the index of its
 * shapes that the live overlay marks ({@link ShapeIndex}). UI thread only, but for the worker.
 */
final class Drawing {
    private final DiagramPane pane;
    private final ParslEditor editor;
    private final ScriptDocument document;
    private final SceneCanvas canvas;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "parpe-diagram");
        t.setDaemon(true);
        return t;
    });
    private final AtomicLong generation = new AtomicLong();
    private Projection shown;
    /** The text scale the ring or the wheel shown is laid out with ({@link #readable}). */
    private double textScale = 1;

    Drawing(DiagramPane pane, ParslEditor editor, ScriptDocument document, SceneCanvas canvas) {
        this.pane = pane;
        this.editor = editor;
        this.document = document;
        this.canvas = canvas;
    }

    /** Projects the current text as view {@code v} on {@code subject} on the worker; the newest request wins. */
    void relayout(View v, String subject, NodePlaces at) {
        long gen = generation.incrementAndGet();
        document.whenLoaded(loaded -> {
            if (gen != generation.get() || canvas.control().isDisposed()) {
                return;
            }
            var display = canvas.control().getDisplay();
            worker.execute(() -> {
                if (gen != generation.get()) {
                    return;
                }
                Projection p = Projection.of(loaded, v, subject, at);
                if (!display.isDisposed()) {
                    display.asyncExec(() -> {
                        if (gen == generation.get() && !canvas.control().isDisposed()) {
                            shown = readable(p);
                            pane.show(shown);
                        }
                    });
                }
            });
        });
    }

    /** No more layouts: the pane is gone. */
    void dispose() {
        generation.incrementAndGet();
        worker.shutdownNow();
    }

    /** The projection shown, or {@code null} before the first. */
    Projection shown() {
        return shown;
    }

    /** Whether the drawing shows the editor's current text. */
    boolean current() {
        return shown != null && shown.text().equals(editor.document().get());
    }

    /** The text scale the ring or the wheel shown is laid out with (1 for the other views). */
    double textScale() {
        return textScale;
    }

    /** The script of the open text as loaded now, or {@code null} when it does not load. */
    Program program() {
        return document.loaded().program();
    }

    /** The open text as loaded now. */
    ScriptDocument.Loaded loaded() {
        return document.loaded();
    }

    /**
     * {@code p} with its ring or wheel laid out with text large enough to read on the canvas as
     * it is now: the canvas would otherwise make small text larger where it lies, and labels laid
     * out apart would meet. A few rounds, as larger text makes the drawing larger.
     */
    private Projection readable(Projection p) {
        textScale = 1;
        if (p.scene() == null || p.ring() == null && p.wheel() == null) {
            return p;
        }
        Projection out = p;
        for (int round = 0; round < 8; round++) {
            double need = canvas.textScale(out.scene(), Layouts.RING_TEXT);
            if (need <= textScale * 1.001) {
                break;
            }
            textScale = need;
            out = p.withTextScale(textScale);
        }
        return out;
    }

    /**
     * The drawing's smallest text is {@code steps} × 2 points larger than normal (the window's
     * zoom, {@link Zoom}): other text grows to it, and the ring and the wheel are laid out again
     * so that their labels stay apart.
     */
    void zoom(int steps) {
        canvas.zoom(Zoom.factor(canvas.control().getDisplay().getSystemFont(), steps));
        laidOutAgain();
    }

    /** The canvas changed size or the zoom: the ring or the wheel is laid out again for it. */
    void laidOutAgain() {
        if (shown != null && (shown.ring() != null || shown.wheel() != null) && shown.scene() != null) {
            double before = textScale;
            Projection p = readable(shown.withTextScale(1));
            if (textScale != before) {
                shown = p;
                pane.redrawn(p);
            }
        }
    }
}
