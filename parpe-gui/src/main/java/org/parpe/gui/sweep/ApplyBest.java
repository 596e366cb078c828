package org.parpe.gui.sweep;

import java.util.Map;
import org.eclipse.jface.text.BadLocationException;
import org.eclipse.jface.text.IRewriteTarget;
import org.parpe.core.load.LoadResult;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.core.model.Parameter;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.sweep.ParameterDefaults;
import org.parpe.sim.sweep.SweepException;

/**
 * "Apply best": writes values as the parameters' defaults ({@code value="..."}) into the
 * editor's text as one undoable edit. The text is read as it is now (it may have changed since
 * the sweep), rewritten by the engine's {@link ParameterDefaults}, and only the span between
 * the first and the last changed character is replaced, so the rest of the document, its
 * markers and its undo history stay as they were. Nothing is saved to the file.
 */
final class ApplyBest {
    private ApplyBest() {
    }

    /**
     * Writes {@code values} into {@code editor}'s text ({@code loaded}, as it is now); returns a line
     * saying what changed. Throws with one line when the script does not load, a parameter is
     * gone or a value is outside its bounds now.
     */
    static String apply(ParslEditor editor, ScriptDocument.Loaded loaded, Map<String, Double> values) throws SweepException {
        if (values.isEmpty()) {
            throw new SweepException(ToolMsg.SWEEP_NO_RESULT.text());
        }
        String text = loaded.text();
        LoadResult r = loaded.result();
        if (r.program() == null) {
            throw new SweepException(ToolMsg.SWEEP_SCRIPT_HAS_ERRORS.text());
        }
        for (Map.Entry<String, Double> v : values.entrySet()) {
            Parameter p = r.program().parameters().stream().filter(q -> q.name().equals(v.getKey())).findFirst()
                    .orElseThrow(() -> new SweepException(ToolMsg.SWEEP_PARAMETER_GONE.text(v.getKey())));
            String problem = p.check(v.getValue());
            if (problem != null) {
                throw new SweepException(ToolMsg.SWEEP_BOUNDS_CHANGED.text(problem));
            }
        }
        String out = ParameterDefaults.rewrite(loaded.file(), text, r.program().parameters(), values);
        replaceChanged(editor, text, out);
        return Results.describe(values);
    }

    /** Replaces the part of the document where {@code before} and {@code after} differ, as one undo step. */
    private static void replaceChanged(ParslEditor editor, String before, String after) {
        int start = 0;
        int max = Math.min(before.length(), after.length());
        while (start < max && before.charAt(start) == after.charAt(start)) {
            start++;
        }
        int end = 0;
        while (end < max - start && before.charAt(before.length() - 1 - end) == after.charAt(after.length() - 1 - end)) {
            end++;
        }
        if (start == before.length() && start == after.length()) {
            return;
        }
        IRewriteTarget target = editor.viewer().getRewriteTarget();
        target.beginCompoundChange();
        try {
            editor.document().replace(start, before.length() - end - start, after.substring(start, after.length() - end));
        } catch (BadLocationException e) {
            throw new IllegalStateException("the span " + start + ".." + (before.length() - end)
                    + " lies outside a document of " + before.length() + " characters", e);
        } finally {
            target.endCompoundChange();
        }
    }
}
