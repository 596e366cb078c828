package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.edit.EditRefused;
import org.parpe.core.edit.ElementWriter;
import org.parpe.core.edit.Replacement;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.load.ListItem;
import org.parpe.core.model.Automaton;
import org.parpe.core.text.EditMsg;

/**
 * Edits of an automaton's cycle made on its ring: remove a state, move a state to another place
 * in the cycle, set or clear a state's exit condition. Like {@link DiagramEdits}, each is one
 * {@link TextEdit} that replaces only characters of the {@code states} and {@code times} values,
 * so the rest of the text stays byte for byte; a state's definition in {@code <states>} is
 * never touched (another automaton may use it).
 */
public final class RingEdits {
    private RingEdits() {
    }

    /**
     * Removes item {@code state} from {@code a}'s {@code states} and, when written, from its
     * {@code times}: the item goes with the comma before it (after it, for the first item); the
     * spacing of the other items stays.
     */
    public static TextEdit removeState(String text, Automaton a, int state) {
        int n = checked(a, state);
        if (n == 1) {
            throw new EditRefused(EditMsg.LAST_STATE, a.name());
        }
        List<Replacement> edits = new ArrayList<>();
        for (String attr : List.of("states", "times")) {
            List<int[]> items = items(text, a, attr);
            if (items != null) {
                int from = state == 0 ? items.get(0)[0] : items.get(state - 1)[1];
                int to = state == 0 ? items.get(1)[0] : items.get(state)[1];
                edits.add(new Replacement(from, to - from, ""));
            }
        }
        return new TextEdit(edits);
    }

    /**
     * Moves state {@code from} of {@code a}'s cycle to place {@code to}: the items of
     * {@code states} (and of {@code times}, so each state keeps its duration and exit) change
     * places, the spacing between them stays where it was.
     */
    public static TextEdit moveState(String text, Automaton a, int from, int to) {
        checked(a, from);
        checked(a, to);
        List<Replacement> edits = new ArrayList<>();
        if (from == to) {
            return new TextEdit(edits);
        }
        for (String attr : List.of("states", "times")) {
            List<int[]> items = items(text, a, attr);
            if (items == null) {
                continue;
            }
            List<int[]> order = new ArrayList<>(items);
            order.add(to, order.remove(from));
            for (int k = Math.min(from, to); k <= Math.max(from, to); k++) {
                int[] place = items.get(k);
                int[] moved = order.get(k);
                edits.add(new Replacement(place[0], place[1] - place[0], text.substring(moved[0], moved[1])));
            }
        }
        return new TextEdit(edits);
    }

    /**
     * Gives state {@code state} of {@code a} the exit condition {@code exit} (an expression), or
     * none when {@code exit} is blank: the {@code [E]} of that item of {@code times} is replaced,
     * added or removed, its duration kept. Without {@code times} (every state 1 s) the attribute
     * is written.
     */
    public static TextEdit setExit(String text, Automaton a, int state, String exit) {
        int n = checked(a, state);
        String condition = exit.isBlank() ? "" : "[" + exit.trim() + "]";
        SourceSpan.Range r = ScriptEdits.span(a.pos()).value("times");
        if (r == null) {
            if (condition.isEmpty()) {
                return new TextEdit(List.of());
            }
            List<String> times = new ArrayList<>(Collections.nCopies(n, "1"));
            times.set(state, "1" + condition);
            return ScriptEdits.setAttribute(text, a.pos(), "times", String.join(", ", times));
        }
        int[] item = items(text, a, "times").get(state);
        int bracket = text.indexOf('[', item[0]);
        if (bracket < 0 || bracket >= item[1]) {
            return TextEdit.of(item[1], 0, ElementWriter.attributeText(condition, text.charAt(r.offset() - 1)));
        }
        int from = ScriptEdits.trim(text, item[0], bracket)[1];
        return TextEdit.of(from, item[1] - from, ElementWriter.attributeText(condition, text.charAt(r.offset() - 1)));
    }

    private static int checked(Automaton a, int state) {
        if (a.table()) {
            throw new EditRefused(EditMsg.TABLE_EDIT_ROWS, a.name());
        }
        int n = a.states().size();
        if (state < 0 || state >= n) {
            throw new EditRefused(EditMsg.NO_SUCH_STATE, a.name(), n - 1, state);
        }
        return n;
    }

    /** The items of attribute {@code attr}, each trimmed of spaces, or {@code null} when it is not written. */
    private static List<int[]> items(String text, Automaton a, String attr) {
        SourceSpan.Range r = ScriptEdits.span(a.pos()).value(attr);
        if (r == null) {
            return null;
        }
        List<int[]> out = new ArrayList<>();
        for (int[] item : ListItem.ranges(text, r.offset(), r.end(), ',')) {
            out.add(ScriptEdits.trim(text, item[0], item[1]));
        }
        if (out.size() != a.states().size()) {
            throw new EditRefused(EditMsg.ITEMS_MISMATCH, a.name(), a.states().size(), out.size(), attr);
        }
        return out;
    }
}
