package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.edit.EditRefused;
import org.parpe.core.edit.ElementWriter;
import org.parpe.core.edit.Replacement;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.edit.SectionEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.MainDef;
import org.parpe.core.model.Program;
import org.parpe.core.text.EditMsg;
import org.parpe.core.text.Msg;

/**
 * Edits made on the program lane and the swimlanes that add elements: an automaton instance
 * on a group to a behavior, and a new behavior (defined, and run by a new {@code <main>}
 * entry). A new element goes after its last sibling on a line of its own with that sibling's
 * indentation, or, in an element with no children yet, two spaces deeper than its parent; as
 * with {@link DiagramEdits} nothing else of the text changes.
 */
public final class BehaviorEdits {
    private BehaviorEdits() {
    }

    /** Adds an instance of automaton {@code automaton} on group {@code group} as {@code b}'s last item. */
    public static TextEdit addInstance(String text, Behavior b, String automaton, String group) {
        ElementWriter.name(automaton, "automaton");
        if (group.isBlank()) {
            throw new EditRefused(EditMsg.INSTANCE_NEEDS_GROUP);
        }
        SourcePos last = b.items().isEmpty() ? null : b.items().get(b.items().size() - 1).pos();
        return ScriptEdits.appendChild(text, ScriptEdits.span(b.pos()), b.name(),
                last == null ? null : ScriptEdits.span(last), ElementWriter.tag(automaton).attr("group", group.trim()).empty());
    }

    /**
     * Defines behavior {@code name} with one instance of {@code automaton} on {@code group}
     * after the file's last behavior, and runs it from a new entry at the end of {@code <main>}
     * (with {@code time} when it is not blank); {@code <behaviors>} and {@code <main>} are
     * written when the file has none yet ({@link SectionEdits}).
     */
    public static TextEdit addBehavior(String text, Program p, String name, String automaton, String group,
                                       String time) {
        ElementWriter.name(name, "behavior");
        if (p.behavior(name).isPresent()) {
            throw new EditRefused(EditMsg.NAME_TAKEN, Msg.kind("behavior"), name);
        }
        String instance = ElementWriter.tag(ElementWriter.name(automaton, "automaton")).attr("group", group.trim()).empty();
        String entry = ElementWriter.tag(name).attrIfGiven("time", time == null ? null : time.trim()).empty();
        // <main> before <behaviors> when both are new and go to the same place (SectionEdits.ORDER)
        List<Replacement> edits = new ArrayList<>(SectionEdits.add(text, p.file(), indent -> entry, "main")
                .replacements());
        edits.addAll(SectionEdits.add(text, p.file(), indent -> ElementWriter.tag(name).lines(indent, List.of(instance)),
                "behaviors").replacements());
        return new TextEdit(edits);
    }

    /**
     * Runs the defined behavior {@code behavior} from a new entry at the end of {@code <main>}
     * (what dropping a free behavior of the workbench on the program lane writes; a {@code <main>}
     * is written when the file has none); refused for a behavior with macros, whose entry needs
     * their values.
     */
    public static TextEdit addEntry(String text, Program p, String behavior) {
        Behavior b = p.behavior(behavior).orElseThrow(() -> new EditRefused(EditMsg.NO_BEHAVIOR, behavior));
        if (!b.macros().isEmpty()) {
            // PARSL.md §8: every entry gives each macro a value, which a drop does not know
            throw new EditRefused(EditMsg.TAKES_MACROS, behavior, String.join(", ", b.macros()));
        }
        return SectionEdits.add(text, p.file(), indent -> ElementWriter.tag(behavior).empty(), "main");
    }

    /**
     * Removes entry {@code index} of {@code <main>} with the line it stands on when nothing else
     * is written there; the behavior stays defined.
     */
    public static TextEdit removeEntry(String text, MainDef main, int index) {
        int n = main.entries().size();
        if (index < 0 || index >= n) {
            throw new EditRefused(EditMsg.NO_SUCH_ENTRY, n - 1, index);
        }
        return ScriptEdits.removeElement(text, ScriptEdits.span(main.entries().get(index).pos()));
    }
}
