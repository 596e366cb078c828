package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.load.ListItem;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.MainDef;
import org.parpe.core.model.Program;
import org.parpe.core.print.ProgramPrinter;

/**
 * Turns an edit made on a diagram into a {@link TextEdit} of the script's text, through the
 * source spans of the model's nodes: only the attribute values or elements that change are
 * replaced, so comments, order and layout stay as written. {@code text} is always the text of
 * the file the node was read from, as it was when the program was loaded. An edit that cannot
 * be made is refused with an {@link IllegalArgumentException} whose message says why.
 */
public final class DiagramEdits {
    private DiagramEdits() {
    }

    /**
     * Sets attribute {@code name} of the element of {@code node} to {@code value} (for example
     * an instance's {@code phase} or {@code offset}, an entry's {@code time}): its value is
     * replaced, or, when it is not written, the attribute is added after the last one.
     */
    public static TextEdit setAttribute(String text, SourcePos node, String name, String value) {
        SourceSpan s = span(node);
        SourceSpan.Range r = s.value(name);
        if (r != null) {
            return TextEdit.of(r.offset(), r.length(), escape(value, text.charAt(r.offset() - 1)));
        }
        return TextEdit.of(afterAttributes(text, s), 0, " " + name + "=\"" + escape(value, '"') + "\"");
    }

    /**
     * Gives state {@code state} of automaton {@code a} the duration {@code duration} (an
     * expression): the duration of that item of {@code times} is replaced, its exit condition
     * kept; without {@code times} (every state 1 s) the attribute is written.
     */
    public static TextEdit retime(String text, Automaton a, int state, String duration) {
        int n = a.states().size();
        if (state < 0 || state >= n) {
            throw new IllegalArgumentException("automaton '" + a.name() + "' has states 0.." + (n - 1) + ", not " + state);
        }
        SourceSpan.Range r = span(a.pos()).value("times");
        if (r == null) {
            List<String> times = new ArrayList<>(Collections.nCopies(n, "1"));
            times.set(state, duration);
            return setAttribute(text, a.pos(), "times", String.join(", ", times));
        }
        List<int[]> items = ListItem.ranges(text, r.offset(), r.end(), ',');
        int[] item = trim(text, items.get(state)[0], items.get(state)[1]);
        int bracket = text.indexOf('[', item[0]);
        int end = bracket >= 0 && bracket < item[1] ? trim(text, item[0], bracket)[1] : item[1];
        return TextEdit.of(item[0], end - item[0], escape(duration, text.charAt(r.offset() - 1)));
    }

    /**
     * Moves entry {@code from} of {@code <main>} to position {@code to}: the entries' elements
     * change places; the text between them (layout, comments) stays where it was.
     */
    public static TextEdit moveEntry(String text, MainDef main, int from, int to) {
        int n = main.entries().size();
        if (from < 0 || from >= n || to < 0 || to >= n) {
            throw new IllegalArgumentException("<main> has entries 0.." + (n - 1) + "; cannot move " + from + " to " + to);
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
            SourceSpan moved = span(main.entries().get(order.get(k)).pos());
            out.append(text, moved.start(), moved.end());
            if (k < hi) {
                out.append(text, span(main.entries().get(k).pos()).end(), span(main.entries().get(k + 1).pos()).start());
            }
        }
        int start = span(main.entries().get(lo).pos()).start();
        return TextEdit.of(start, span(main.entries().get(hi).pos()).end() - start, out.toString());
    }

    /**
     * Appends state {@code state} with duration {@code duration} to automaton {@code a}'s cycle.
     * A state that {@code p} does not define yet is defined after the file's last state (in a
     * new {@code <states>} when the file has none, {@link SectionEdits}), holding 0 degrees.
     */
    public static TextEdit addState(String text, Program p, Automaton a, String state, String duration) {
        if (a.table()) {
            throw new IllegalArgumentException("'" + a.name() + "' is a gait table: add a row to its table instead");
        }
        SourceSpan s = span(a.pos());
        List<TextEdit.Replacement> edits = new ArrayList<>();
        SourceSpan.Range states = s.value("states");
        char q = text.charAt(states.offset() - 1);
        edits.add(new TextEdit.Replacement(trim(text, states.offset(), states.end())[1], 0, ", " + escape(state, q)));
        SourceSpan.Range times = s.value("times");
        if (times != null) {
            edits.add(new TextEdit.Replacement(trim(text, times.offset(), times.end())[1], 0,
                    ", " + escape(duration, text.charAt(times.offset() - 1))));
        } else if (!duration.trim().equals("1")) {
            List<String> all = new ArrayList<>(Collections.nCopies(a.states().size(), "1"));
            all.add(duration);
            edits.addAll(setAttribute(text, a.pos(), "times", String.join(", ", all)).replacements());
        }
        if (p.state(state).isEmpty()) {
            String name = BehaviorEdits.name(state.trim(), "state");
            edits.addAll(SectionEdits.add(text, p.file(), indent -> "<" + name + " angles=\"0\"/>", "states").replacements());
        }
        return new TextEdit(edits);
    }

    static SourceSpan span(SourcePos node) {
        if (node.span() == null) {
            throw new IllegalArgumentException(node + " was not read from a file's text; it cannot be edited there");
        }
        return node.span();
    }

    /** Where a new attribute goes: after the last attribute's closing quote, or after the name. */
    private static int afterAttributes(String text, SourceSpan s) {
        int at = s.start() + 1;
        for (SourceSpan.Range r : s.values().values()) {
            at = Math.max(at, r.end() + 1);
        }
        if (at == s.start() + 1) {
            while (at < s.tagEnd() && !Character.isWhitespace(text.charAt(at))) {
                at++;
            }
        }
        return at;
    }

    static int[] trim(String text, int from, int to) {
        while (from < to && Character.isWhitespace(text.charAt(from))) {
            from++;
        }
        while (to > from && Character.isWhitespace(text.charAt(to - 1))) {
            to--;
        }
        return new int[] {from, to};
    }

    /** {@code value} written between {@code quote}s. */
    static String escape(String value, char quote) {
        String s = ProgramPrinter.attributeText(value);
        return quote == '\'' ? s.replace("&quot;", "\"").replace("'", "&apos;") : s;
    }
}
