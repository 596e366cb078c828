package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.edit.EditRefused;
import org.parpe.core.edit.ElementWriter;
import org.parpe.core.edit.Replacement;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.edit.SectionEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.load.ListItem;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.MainDef;
import org.parpe.core.model.Program;
import org.parpe.core.text.EditMsg;

/**
 * Turns an edit made on a diagram into a {@link TextEdit} of the script's text through the
 * source spans of the model's nodes ({@link ScriptEdits}): only the attribute values or elements that change are
 * replaced, so comments, order and layout stay as written. {@code text} is always the text of
 * the file the node was read from, as it was when the program was loaded. An edit that cannot
 * be made is refused with an {@link EditRefused} whose message says why.
 */
public final class DiagramEdits {
    private DiagramEdits() {
    }

    /**
     * Gives state {@code state} of automaton {@code a} the duration {@code duration} (an
     * expression): the duration of that item of {@code times} is replaced, its exit condition
     * kept; without {@code times} (every state 1 s) the attribute is written.
     */
    public static TextEdit retime(String text, Automaton a, int state, String duration) {
        int n = a.states().size();
        if (state < 0 || state >= n) {
            throw new EditRefused(EditMsg.NO_SUCH_STATE, a.name(), n - 1, state);
        }
        SourceSpan.Range r = ScriptEdits.span(a.pos()).value("times");
        if (r == null) {
            List<String> times = new ArrayList<>(Collections.nCopies(n, "1"));
            times.set(state, duration);
            return ScriptEdits.setAttribute(text, a.pos(), "times", String.join(", ", times));
        }
        List<int[]> items = ListItem.ranges(text, r.offset(), r.end(), ',');
        int[] item = ScriptEdits.trim(text, items.get(state)[0], items.get(state)[1]);
        int bracket = text.indexOf('[', item[0]);
        int end = bracket >= 0 && bracket < item[1] ? ScriptEdits.trim(text, item[0], bracket)[1] : item[1];
        return TextEdit.of(item[0], end - item[0], ElementWriter.attributeText(duration, text.charAt(r.offset() - 1)));
    }

    /**
     * Moves entry {@code from} of {@code <main>} to position {@code to}: the entries' elements
     * change places; the text between them (layout, comments) stays where it was.
     */
    public static TextEdit moveEntry(String text, MainDef main, int from, int to) {
        int n = main.entries().size();
        if (from < 0 || from >= n || to < 0 || to >= n) {
            throw new EditRefused(EditMsg.CANNOT_MOVE_ENTRY, n - 1, from, to);
        }
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            order.add(i);
        }
        order.add(to, order.remove(from));
        int lo = Math.min(from, to);
        int hi = Math.max(from, to);
        StringBuilder out = new StringBuilder();
        for (int k = lo; k <= hi; k++) {
            SourceSpan moved = ScriptEdits.span(main.entries().get(order.get(k)).pos());
            out.append(text, moved.start(), moved.end());
            if (k < hi) {
                out.append(text, ScriptEdits.span(main.entries().get(k).pos()).end(),
                        ScriptEdits.span(main.entries().get(k + 1).pos()).start());
            }
        }
        int start = ScriptEdits.span(main.entries().get(lo).pos()).start();
        return TextEdit.of(start, ScriptEdits.span(main.entries().get(hi).pos()).end() - start, out.toString());
    }

    /**
     * Appends state {@code state} with duration {@code duration} to automaton {@code a}'s cycle.
     * A state that {@code p} does not define yet is defined after the file's last state (in a
     * new {@code <states>} when the file has none, {@link SectionEdits}), holding 0 degrees.
     */
    public static TextEdit addState(String text, Program p, Automaton a, String state, String duration) {
        if (a.table()) {
            throw new EditRefused(EditMsg.TABLE_ADD_ROW, a.name());
        }
        SourceSpan s = ScriptEdits.span(a.pos());
        List<Replacement> edits = new ArrayList<>();
        SourceSpan.Range states = s.value("states");
        char q = text.charAt(states.offset() - 1);
        edits.add(new Replacement(ScriptEdits.trim(text, states.offset(), states.end())[1], 0,
                ", " + ElementWriter.attributeText(state, q)));
        SourceSpan.Range times = s.value("times");
        if (times != null) {
            edits.add(new Replacement(ScriptEdits.trim(text, times.offset(), times.end())[1], 0,
                    ", " + ElementWriter.attributeText(duration, text.charAt(times.offset() - 1))));
        } else if (!duration.trim().equals("1")) {
            List<String> all = new ArrayList<>(Collections.nCopies(a.states().size(), "1"));
            all.add(duration);
            edits.addAll(ScriptEdits.setAttribute(text, a.pos(), "times", String.join(", ", all)).replacements());
        }
        if (p.state(state).isEmpty()) {
            String name = ElementWriter.name(state.trim(), "state");
            edits.addAll(SectionEdits.add(text, p.file(), indent -> ElementWriter.tag(name).attr("angles", "0").empty(),
                    "states").replacements());
        }
        return new TextEdit(edits);
    }
}
