package org.parpe.gui.editor;

import org.eclipse.jface.text.DocumentEvent;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IDocumentListener;
import org.eclipse.swt.widgets.Control;

/**
 * Runs a view's refresh a moment after its document changes, once for the changes made
 * meanwhile: once the current event is handled, or, for a text over {@value #QUICK_CHARS}
 * characters (reading it takes longer than a keystroke should), {@value #PAUSE_MS} ms after
 * the change. Never while {@code owner} is disposed. UI thread only.
 */
public final class AfterChange {
    /** Texts up to this many characters are read again at once. */
    public static final int QUICK_CHARS = 200_000;
    /** The pause before a longer text is read again. */
    public static final int PAUSE_MS = 300;

    private final Control owner;
    private final IDocument document;
    private final Runnable refresh;
    private boolean pending;

    /** Runs {@code refresh} soon after each change of {@code document}, while {@code owner} lives. */
    public AfterChange(Control owner, IDocument document, Runnable refresh) {
        this.owner = owner;
        this.document = document;
        this.refresh = refresh;
        document.addDocumentListener(new IDocumentListener() {
            @Override
            public void documentAboutToBeChanged(DocumentEvent event) {
            }

            @Override
            public void documentChanged(DocumentEvent event) {
                schedule();
            }
        });
    }

    /** Runs the refresh soon (as after a change), unless it is already due. */
    public void schedule() {
        if (pending || owner.isDisposed()) {
            return;
        }
        pending = true;
        Runnable r = () -> {
            pending = false;
            if (!owner.isDisposed()) {
                refresh.run();
            }
        };
        if (document.getLength() > QUICK_CHARS) {
            owner.getDisplay().timerExec(PAUSE_MS, r);
        } else {
            owner.getDisplay().asyncExec(r);
        }
    }
}
