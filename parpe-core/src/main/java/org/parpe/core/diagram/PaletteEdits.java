package org.parpe.core.diagram;

import java.util.Collections;
import java.util.List;
import org.parpe.core.edit.EditRefused;
import org.parpe.core.edit.ElementWriter;
import org.parpe.core.edit.SectionEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.model.Program;
import org.parpe.core.text.EditMsg;
import org.parpe.core.text.Msg;

/**
 * The edits of the diagram palette that define something new: a group of modules, a
 * parameter, a pose (a named state with its angles), a phase automaton, a gait table. Each new
 * element goes after the last one of its kind in the file, on a line of its own with that one's
 * indentation, and its section is written when the file has none yet ({@link SectionEdits}, so
 * a script can be built from an empty file); its name must not be taken. Nothing else of the
 * text changes.
 */
public final class PaletteEdits {
    private PaletteEdits() {
    }

    /** Defines group {@code name} of modules {@code elements} (as the {@code elements} attribute is written). */
    public static TextEdit addGroup(String text, Program p, String name, String elements) {
        free(p.group(name).isPresent(), name, "group");
        String e = element(name, "group").attr("elements", value(elements, "elements")).empty();
        return SectionEdits.add(text, p.file(), indent -> e, "robot", "structure");
    }

    /**
     * Defines parameter {@code name} (PARSL.md §3) with default {@code value} and, when they are
     * not blank, its bounds {@code min} and {@code max} and the {@code label} of its entry field.
     */
    public static TextEdit addParameter(String text, Program p, String name, String value, String min, String max,
                                        String label) {
        free(p.parameters().stream().anyMatch(x -> x.name().equals(name)), name, "parameter");
        ElementWriter e = element(name, "parameter").attr("value", value(value, "value"));
        for (String[] optional : List.of(new String[] {"min", min}, new String[] {"max", max}, new String[] {"label", label})) {
            if (optional[1] != null && !optional[1].isBlank()) {
                e.attr(optional[0], value(optional[1], optional[0]));
            }
        }
        String written = e.empty();
        return SectionEdits.add(text, p.file(), indent -> written, "parameters");
    }

    /** Defines state (a pose) {@code name} with {@code angles} (one, or one per module of its group). */
    public static TextEdit addPose(String text, Program p, String name, String angles) {
        free(p.state(name).isPresent(), name, "state");
        String e = element(name, "state").attr("angles", value(angles, "angles")).empty();
        return SectionEdits.add(text, p.file(), indent -> e, "states");
    }

    /**
     * Defines phase automaton {@code name} cycling through {@code states} (defined states, comma
     * separated), with {@code times} when it is not blank.
     */
    public static TextEdit addAutomaton(String text, Program p, String name, String states, String times) {
        free(p.automaton(name).isPresent(), name, "automaton");
        String e = element(name, "automaton").attr("states", value(states, "states"))
                .attrIfGiven("times", times == null ? null : times.trim()).empty();
        return SectionEdits.add(text, p.file(), indent -> e, "automata");
    }

    /**
     * Defines gait table {@code name} with {@code rows} (each a comma-separated list of angles;
     * PARSL.md §6) and {@code times} when it is not blank: one row per line.
     */
    public static TextEdit addGaitTable(String text, Program p, String name, List<String> rows, String times) {
        free(p.automaton(name).isPresent(), name, "automaton");
        if (rows.isEmpty() || rows.stream().anyMatch(String::isBlank)) {
            throw new EditRefused(EditMsg.TABLE_NEEDS_ROWS);
        }
        ElementWriter table = element(name, "gait table").attrIfGiven("times", times == null ? null : times.trim());
        List<String> lines = rows.stream().map(row -> ElementWriter.text(row.trim())).toList();
        return SectionEdits.add(text, p.file(), indent -> table.lines(indent, lines), "automata");
    }

    /**
     * Adds gait table {@code name} of {@code rows} rows × {@code modules} columns of 0 (every
     * module level), to be filled in the grid editor; the counts are whole numbers as typed,
     * from 1 to 1000, else the edit is refused with a message naming the value.
     */
    public static TextEdit addGaitTable(String text, Program p, String name, String rows, String modules, String times) {
        int r = count(rows, "rows", 1000);
        int m = count(modules, "modules", 1000);
        String row = String.join(", ", Collections.nCopies(m, "0"));
        return addGaitTable(text, p, name, Collections.nCopies(r, row), times);
    }

    private static int count(String n, String what, int max) {
        int v;
        try {
            v = Integer.parseInt(n == null ? "" : n.trim());
        } catch (NumberFormatException e) {
            throw new EditRefused(EditMsg.COUNT_NOT_WHOLE, what, max, n);
        }
        if (v < 1 || v > max) {
            throw new EditRefused(EditMsg.COUNT_RANGE, what, max, v);
        }
        return v;
    }

    private static void free(boolean taken, String name, String what) {
        if (taken) {
            throw new EditRefused(EditMsg.NAME_TAKEN, Msg.kind(what), name);
        }
    }

    private static String value(String v, String attribute) {
        if (v == null || v.isBlank()) {
            throw new EditRefused(EditMsg.EMPTY_ATTRIBUTE, attribute);
        }
        return v.trim();
    }

    private static ElementWriter element(String name, String what) {
        return ElementWriter.tag(ElementWriter.name(name, what));
    }
}
