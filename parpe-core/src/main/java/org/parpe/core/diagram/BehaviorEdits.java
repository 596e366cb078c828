package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.MainDef;
import org.parpe.core.model.Program;

/**
 * Edits made on the program lane and the swimlanes that add elements: an automaton instance
 * on a group to a behavior, and a new behavior (defined, and run by a new {@code <main>}
 * entry). A new element goes after its last sibling on a line of its own with that sibling's
 * indentation, or, in an element with no children yet, two spaces deeper than its parent; as
 * with {@link DiagramEdits} nothing else of the text changes.
 */
public final class BehaviorEdits {
    private static final Pattern NAME = Pattern.compile("[A-Za-z_][A-Za-z0-9_.-]*");

    private BehaviorEdits() {
    }

    /** Adds an instance of automaton {@code automaton} on group {@code group} as {@code b}'s last item. */
    public static TextEdit addInstance(String text, Behavior b, String automaton, String group) {
        name(automaton, "automaton");
        if (group.isBlank()) {
            throw new IllegalArgumentException("an instance needs a group");
        }
        SourcePos last = b.items().isEmpty() ? null : b.items().get(b.items().size() - 1).pos();
        return appendChild(text, DiagramEdits.span(b.pos()), b.name(), last,
                "<" + automaton + " group=\"" + DiagramEdits.escape(group.trim(), '"') + "\"/>");
    }

    /**
     * Defines behavior {@code name} with one instance of {@code automaton} on {@code group}
     * after the file's last behavior, and runs it from a new entry at the end of {@code <main>}
     * (with {@code time} when it is not blank); {@code <behaviors>} and {@code <main>} are
     * written when the file has none yet ({@link SectionEdits}).
     */
    public static TextEdit addBehavior(String text, Program p, String name, String automaton, String group,
                                       String time) {
        name(name, "behavior");
        if (p.behavior(name).isPresent()) {
            throw new IllegalArgumentException("a behavior named '" + name + "' exists already");
        }
        String quoted = DiagramEdits.escape(group.trim(), '"');
        String instance = "<" + name(automaton, "automaton") + " group=\"" + quoted + "\"/>";
        String entry = "<" + name + (time == null || time.isBlank() ? "" : " time=\"" + DiagramEdits.escape(time.trim(), '"')
                + "\"") + "/>";
        // <main> before <behaviors> when both are new and go to the same place (SectionEdits.ORDER)
        List<TextEdit.Replacement> edits = new ArrayList<>(SectionEdits.add(text, p.file(), indent -> entry, "main")
                .replacements());
        edits.addAll(SectionEdits.add(text, p.file(), indent -> "<" + name + ">\n" + indent + "  " + instance + "\n" + indent
                + "</" + name + ">", "behaviors").replacements());
        return new TextEdit(edits);
    }

    /**
     * Runs the defined behavior {@code behavior} from a new entry at the end of {@code <main>}
     * (what dropping a free behavior of the workbench on the program lane writes; a {@code <main>}
     * is written when the file has none); refused for a behavior with macros, whose entry needs
     * their values.
     */
    public static TextEdit addEntry(String text, Program p, String behavior) {
        Behavior b = p.behavior(behavior).orElseThrow(() -> new IllegalArgumentException(
                "there is no behavior '" + behavior + "'"));
        if (!b.macros().isEmpty()) {
            // PARSL.md §8: every entry gives each macro a value, which a drop does not know
            throw new IllegalArgumentException("behavior '" + behavior + "' takes macros (" + String.join(", ", b.macros())
                    + "); write its <main> entry with their values in the text");
        }
        return SectionEdits.add(text, p.file(), indent -> "<" + behavior + "/>", "main");
    }

    /**
     * Removes entry {@code index} of {@code <main>} with the line it stands on when nothing else
     * is written there; the behavior stays defined.
     */
    public static TextEdit removeEntry(String text, MainDef main, int index) {
        int n = main.entries().size();
        if (index < 0 || index >= n) {
            throw new IllegalArgumentException("<main> has entries 0.." + (n - 1) + ", not " + index);
        }
        return removeElement(text, DiagramEdits.span(main.entries().get(index).pos()));
    }

    /** Removes the element {@code s}, with its line when it stands alone on it. */
    static TextEdit removeElement(String text, SourceSpan s) {
        int from = s.start();
        int to = s.end();
        int lineStart = text.lastIndexOf('\n', from - 1) + 1;
        int lineEnd = text.indexOf('\n', to);
        if (text.substring(lineStart, from).isBlank() && lineEnd >= 0 && text.substring(to, lineEnd).isBlank()) {
            from = lineStart;
            to = lineEnd + 1;
        }
        return TextEdit.of(from, to - from, "");
    }

    /** {@code element} as the last child of the element {@code parent} (named {@code tag}), after {@code last}. */
    static TextEdit appendChild(String text, SourceSpan parent, String tag, SourcePos last, String element) {
        if (last != null) {
            SourceSpan ls = DiagramEdits.span(last);
            return TextEdit.of(ls.end(), 0, "\n" + indent(text, ls.start()) + element);
        }
        String indent = indent(text, parent.start());
        if (parent.empty()) {
            return TextEdit.of(parent.tagEnd(), 2, ">\n" + indent + "  " + element + "\n" + indent + "</" + tag + ">");
        }
        int endTag = text.lastIndexOf("</", parent.end() - 1);
        int at = DiagramEdits.trim(text, parent.tagEnd() + 1, endTag)[1];
        return TextEdit.of(at, 0, "\n" + indent + "  " + element);
    }

    /** The spaces before {@code offset} on its line when only spaces are there, else none. */
    static String indent(String text, int offset) {
        int lineStart = text.lastIndexOf('\n', offset - 1) + 1;
        String before = text.substring(lineStart, offset);
        return before.isBlank() ? before : "";
    }

    static String name(String name, String what) {
        if (!NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("'" + name + "' cannot name a " + what
                    + ": a letter or _ first, then letters, digits, _, . or -");
        }
        return name;
    }
}
