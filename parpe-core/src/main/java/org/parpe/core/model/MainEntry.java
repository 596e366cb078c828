package org.parpe.core.model;

import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Expression;
import org.parpe.core.lang.Vocabulary;

/**
 * One behavior invocation in {@code <main>}, resolved: the behavior it runs and, for every
 * automaton instance of that behavior, the group, automaton and mirror flag it runs with.
 *
 * @param behavior   the behavior's name as written
 * @param definition the behavior of that name
 * @param time       run time in seconds, or {@code null}
 * @param exit       exit condition, or {@code null}
 * @param macros     the value of each macro of the behavior, in the behavior's order
 * @param bindings   every instance of the behavior, depth first in document order, resolved for
 *                   this entry
 * @param pos        the element
 */
public record MainEntry(String behavior, Behavior definition, Expression time, Expression exit,
                        List<MacroArg> macros, List<Binding> bindings, SourcePos pos) {

    public MainEntry {
        macros = List.copyOf(macros);
        bindings = List.copyOf(bindings);
    }

    /**
     * A group reference: a group or group-valued macro's name and whether it mirrors. After
     * {@link #groupOf} the instance's {@code !} and a group-valued macro's {@code !} are
     * combined: mirrored when exactly one of them mirrors.
     *
     * @param name   the group's name
     * @param mirror whether every target angle is negated
     */
    public record GroupRef(String name, boolean mirror) {
        /**
         * The reference written {@code name} or {@code !name} (spaces around either part
         * ignored). This is the one place PARSL's {@code !} is read: the loader, the diagrams,
         * the command line and the editor all call it.
         */
        public static GroupRef parse(String written) {
            String g = written.trim();
            boolean mirror = g.startsWith(Vocabulary.MIRROR);
            return new GroupRef(mirror ? g.substring(Vocabulary.MIRROR.length()).trim() : g, mirror);
        }

        /** This reference with a group-valued macro replaced by its value in {@code macros}. */
        public GroupRef through(List<MacroArg> macros) {
            String base = name;
            boolean mirrored = mirror;
            for (MacroArg a : macros) {
                if (a.name().equals(base) && a.group() != null) {
                    base = a.group();
                    mirrored ^= a.mirror();
                }
            }
            return new GroupRef(base, mirrored);
        }
    }

    /**
     * An automaton instance as one entry runs it: references to the declarations, not names.
     *
     * @param instance   the instance element (its attributes' expressions and source position)
     * @param automaton  the automaton it runs, the same object as in {@link Program#automata()}
     * @param group      the group it drives after macro substitution, the same object as in
     *                   {@link Robot#groups()}
     * @param mirrored   whether its target angles are negated ({@code !} on the instance and on
     *                   the macro's value combined)
     * @param conditions the {@code <if>} blocks around it, outermost first
     */
    public record Binding(Instance instance, Automaton automaton, Group group, boolean mirrored,
                          List<Conditional> conditions) {
        public Binding {
            conditions = List.copyOf(conditions);
        }
    }

    /**
     * The group {@code instance} (an instance of this entry's behavior) drives, as bound at load
     * ({@link Binding}); {@code null} when its group macro names no group.
     */
    public Group boundGroup(Instance instance) {
        for (Binding b : bindings) {
            if (b.instance() == instance) {
                return b.group();
            }
        }
        return null;
    }

    /** The group {@code instance} drives when this entry's macro values are applied. */
    public GroupRef groupOf(Instance instance) {
        return instance.groupRef().through(macros);
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
