package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Expression;
import org.parpe.core.lang.Vocabulary;

/**
 * One behavior invocation in {@code <main>}.
 *
 * @param behavior the behavior's name
 * @param time     run time in seconds, or {@code null}
 * @param exit     exit condition, or {@code null}
 * @param macros   the value of each macro of the behavior, in the behavior's order
 * @param pos      the element
 */
public record MainEntry(String behavior, Expression time, Expression exit, List<MacroArg> macros,
                        SourcePos pos) {

    public MainEntry {
        macros = List.copyOf(macros);
    }

    /**
     * The group an instance drives in this entry, with the instance's {@code !} and a
     * group-valued macro's {@code !} combined: mirrored when exactly one of them mirrors.
     *
     * @param name   the group's name
     * @param mirror whether every target angle is negated
     */
    public record GroupRef(String name, boolean mirror) {
        /** The reference written {@code name} or {@code !name} (spaces around either part ignored). */
        public static GroupRef parse(String written) {
            String g = written.trim();
            boolean mirror = g.startsWith(Vocabulary.MIRROR);
            return new GroupRef(mirror ? g.substring(Vocabulary.MIRROR.length()).trim() : g, mirror);
        }
    }

    /** The group {@code instance} drives when this entry runs it. */
    public GroupRef groupOf(Instance instance) {
        GroupRef written = GroupRef.parse(instance.group());
        String base = written.name();
        boolean mirror = written.mirror();
        for (MacroArg a : macros) {
            if (a.name().equals(base) && a.group() != null) {
                base = a.group();
                mirror ^= a.mirror();
            }
        }
        return new GroupRef(base, mirror);
    }

    /**
     * A macro's value for this entry.
     *
     * @param name   the macro
     * @param text   the value as written
     * @param group  for a group-valued macro, the group name without {@code !}; else {@code null}
     * @param mirror for a group-valued macro, whether the value starts with {@code !}
     * @param value  for an expression-valued macro, the expression; else {@code null}
     * @param pos    the attribute
     */
    public record MacroArg(String name, String text, String group, boolean mirror,
                           Expression value, SourcePos pos) {
    }
}
