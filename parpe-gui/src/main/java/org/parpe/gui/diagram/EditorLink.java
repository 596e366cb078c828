package org.parpe.gui.diagram;

import java.util.List;
import java.util.function.Predicate;
import org.eclipse.jface.text.BadLocationException;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.diagram.Scene;
import org.parpe.core.edit.TextEdit;
import org.parpe.gui.diagram.Projection.View;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.text.PanelMsg;

/**
 * The Diagram pane and the editor's text, both ways: a node clicked selects its element in the
 * text, the caret in the text selects the node whose element holds it, and a value written in
 * the edit row, an action's button or a drop becomes one replacement of the document (one Undo
 * step), refused with a message when the text has changed since the drawing was made. UI thread
 * only.
 */
final class EditorLink {
    private final DiagramPane pane;
    private final ParslEditor editor;
    private boolean following;
    private Runnable written;
    private Predicate<String> tables;

    EditorLink(DiagramPane pane, ParslEditor editor) {
        this.pane = pane;
        this.editor = editor;
        editor.widget().addCaretListener(e -> caretAt(e.caretOffset));
    }

    /** A click on the canvas: select the node's element, or open an island's text at its line. */
    void clicked(SourcePos node) {
        Projection shown = pane.shown();
        if (shown == null) {
            return;
        }
        if (node == null) {
            if (shown.view() != View.PHASE) {
                pane.select(null);
            }
            return;
        }
        pane.select(node);
        if (node.span() != null && node.file().equals(shown.file().toString()) && pane.current()) {
            SourceSpan s = node.span();
            following = true;
            try {
                editor.viewer().setSelectedRange(s.start(), s.end() - s.start());
                editor.viewer().revealRange(s.start(), s.end() - s.start());
            } finally {
                following = false;
            }
        } else if (node.line() > 0 && node.file().equals(shown.file().toString())) {
            editor.reveal(node.line(), node.column());
        }
    }

    /** The caret moved in the text: select the innermost drawn node whose element holds it. */
    private void caretAt(int offset) {
        Projection shown = pane.shown();
        if (following || shown == null || shown.scene() == null || !pane.current()) {
            return;
        }
        SourcePos best = null;
        for (var s : shown.scene().shapes()) {
            SourcePos p = s instanceof Scene.Rect r ? r.source() : s instanceof Scene.Sector c ? c.source() : null;
            if (p != null && p.span() != null && p.file().equals(shown.file().toString()) && offset >= p.span().start()
                    && offset <= p.span().end()
                    && (best == null || p.span().end() - p.span().start() < best.span().end() - best.span().start())) {
                best = p;
            }
        }
        if (best != null && !best.equals(pane.selected())) {
            pane.select(best);
        }
    }

    /**
     * Writes {@code value} as field {@code f} of the selected node: the edit's replacements
     * become one replacement of the document (one Undo step).
     */
    void write(Projection.Field f, String value) {
        if (!pane.current()) {
            pane.say(PanelMsg.DIAGRAM_CHANGED.text());
            return;
        }
        if (value.equals(f.value())) {
            return;
        }
        TextEdit edit;
        try {
            edit = f.edit().apply(value.trim());
        } catch (IllegalArgumentException e) {
            pane.say(e.getMessage());
            return;
        }
        apply(edit);
    }

    /** Button {@code a} was pressed with its inputs' {@code values}: write its edit (one Undo step). */
    void act(Projection.Action a, List<String> values) {
        if (!pane.current()) {
            pane.say(PanelMsg.DIAGRAM_CHANGED.text());
            return;
        }
        written = null;
        try {
            apply(a.edit().apply(values));
            if (a.name().equals(Projection.EXPAND.text())) {
                openTable(values.get(0));
            }
            if (written != null) {
                written.run();
            }
        } catch (IllegalArgumentException e) {
            pane.say(e.getMessage());
        } finally {
            written = null;
        }
    }

    /** What to do once the edit being made is in the text (a palette item shows what it added). */
    void whenWritten(Runnable then) {
        written = then;
    }

    /** Applies {@code edit} to the document as one replacement spanning all of its ranges. */
    void apply(TextEdit edit) {
        try {
            editor.apply(edit);
        } catch (BadLocationException e) {
            pane.say(PanelMsg.DIAGRAM_CHANGED_MEANWHILE.text(e.getMessage()));
        }
    }

    /** Opens a gait table the pane has just written with {@code show} (the grid editor's, by table name). */
    void openTablesWith(Predicate<String> show) {
        tables = show;
    }

    /** The grid editor beside the text shows gait table {@code name}. */
    void openTable(String name) {
        if (tables != null) {
            tables.test(name);
        }
    }
}
