package org.parpe.core.diagram;

import java.util.List;
import java.util.function.Predicate;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.model.Program;

/**
 * The edits of the diagram palette that define something new: a group of modules, a pose (a
 * named state with its angles), a phase automaton, a gait table. Each new element goes after
 * the last one of its kind in the file, on a line of its own with that one's indentation (the
 * way {@link BehaviorEdits} adds elements); its name must not be taken. Nothing else of the
 * text changes.
 */
public final class PaletteEdits {
    private PaletteEdits() {
    }

    /** Defines group {@code name} of modules {@code elements} (as the {@code elements} attribute is written). */
    public static TextEdit addGroup(String text, Program p, String name, String elements) {
        free(p.group(name).isPresent(), name, "group");
        return after(text, p, p.robot().groups().stream().filter(g -> !g.implicit()).map(g -> g.pos()).toList(), "group",
                "<" + BehaviorEdits.name(name, "group") + " elements=\"" + value(elements, "elements") + "\"/>");
    }

    /** Defines state (a pose) {@code name} with {@code angles} (one, or one per module of its group). */
    public static TextEdit addPose(String text, Program p, String name, String angles) {
        free(p.state(name).isPresent(), name, "state");
        return after(text, p, p.states().stream().map(s -> s.pos()).toList(), "state",
                "<" + BehaviorEdits.name(name, "state") + " angles=\"" + value(angles, "angles") + "\"/>");
    }

    /**
     * Defines phase automaton {@code name} cycling through {@code states} (defined states, comma
     * separated), with {@code times} when it is not blank.
     */
    public static TextEdit addAutomaton(String text, Program p, String name, String states, String times) {
        free(p.automaton(name).isPresent(), name, "automaton");
        String t = times == null || times.isBlank() ? "" : " times=\"" + DiagramEdits.escape(times.trim(), '"') + "\"";
        return after(text, p, p.automata().stream().map(a -> a.pos()).toList(), "automaton",
                "<" + BehaviorEdits.name(name, "automaton") + " states=\"" + value(states, "states") + "\"" + t + "/>");
    }

    /**
     * Defines gait table {@code name} with {@code rows} (each a comma-separated list of angles;
     * PARSL.md §6) and {@code times} when it is not blank: one row per line.
     */
    public static TextEdit addGaitTable(String text, Program p, String name, List<String> rows, String times) {
        free(p.automaton(name).isPresent(), name, "automaton");
        if (rows.isEmpty() || rows.stream().anyMatch(String::isBlank)) {
            throw new IllegalArgumentException("a gait table needs at least one row, and no row may be empty");
        }
        SourcePos last = last(p, p.automata().stream().map(a -> a.pos()).toList(), "automaton");
        String indent = BehaviorEdits.indent(text, DiagramEdits.span(last).start());
        StringBuilder e = new StringBuilder("<").append(BehaviorEdits.name(name, "gait table"));
        if (times != null && !times.isBlank()) {
            e.append(" times=\"").append(DiagramEdits.escape(times.trim(), '"')).append('"');
        }
        e.append('>');
        for (String row : rows) {
            e.append('\n').append(indent).append("  ").append(DiagramEdits.escape(row.trim(), '"').replace("&quot;", "\""));
        }
        e.append('\n').append(indent).append("</").append(name).append('>');
        return TextEdit.of(DiagramEdits.span(last).end(), 0, "\n" + indent + e);
    }

    private static TextEdit after(String text, Program p, List<SourcePos> siblings, String what, String element) {
        SourcePos last = last(p, siblings, what);
        return TextEdit.of(DiagramEdits.span(last).end(), 0, "\n" + BehaviorEdits.indent(text, DiagramEdits.span(last).start())
                + element);
    }

    /** The last of {@code siblings} written in the program's own file. */
    private static SourcePos last(Program p, List<SourcePos> siblings, String what) {
        Predicate<SourcePos> mine = s -> s != null && s.span() != null && s.file().equals(p.file());
        return siblings.stream().filter(mine).reduce((x, y) -> y).orElseThrow(() -> new IllegalArgumentException(
                "this file defines no " + what + " yet to put a new one after"));
    }

    private static void free(boolean taken, String name, String what) {
        if (taken) {
            throw new IllegalArgumentException("a " + what + " named '" + name + "' exists already");
        }
    }

    private static String value(String v, String attribute) {
        if (v == null || v.isBlank()) {
            throw new IllegalArgumentException(attribute + " must not be empty");
        }
        return DiagramEdits.escape(v.trim(), '"');
    }
}
