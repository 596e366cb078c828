package org.parpe.gui.diagram;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.parpe.core.diagram.DiagramEdits;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.diagram.Ring;
import org.parpe.core.diagram.RingEdits;
import org.parpe.core.model.Automaton;
import org.parpe.gui.diagram.Projection.Action;
import org.parpe.gui.diagram.Projection.Field;
import org.parpe.gui.diagram.Projection.Target;
import org.parpe.gui.text.PanelMsg;

/**
 * What can be edited on one state of an automaton's ring: its duration, its exit condition and
 * (when its definition is in the open file) its angles as fields; its place in the cycle by
 * dragging its arc onto another one's or with the Earlier / Later buttons (for keyboard
 * users); and Remove. Every edit goes through {@link DiagramEdits} or {@link RingEdits}.
 */
final class StateTargets {
    private StateTargets() {
    }

    /** The target of {@code arc} of {@code a}'s ring, {@code a} being a phase automaton in the open file. */
    static Target of(String text, Path file, Automaton a, Ring.Arc arc) {
        int k = arc.index();
        int n = a.states().size();
        List<Field> fields = new ArrayList<>();
        fields.add(new Field("duration", arc.duration(), v -> DiagramEdits.retime(text, a, k, v)));
        fields.add(new Field("exit", arc.exit() == null ? "" : arc.exit(), v -> RingEdits.setExit(text, a, k, v)));
        // the automaton holds its states, bound at load: the arc's state is a.states().get(k)
        Optional.of(a.states().get(k)).filter(d -> Projection.mine(d.pos(), file)).ifPresent(d -> fields.add(new Field("angles",
                d.pos().span().value("angles") == null ? "" : String.join(", ", arc.angles()),
                v -> ScriptEdits.setAttribute(text, d.pos(), "angles", v))));
        List<Action> actions = new ArrayList<>();
        if (k > 0) {
            actions.add(new Action(PanelMsg.DIAGRAM_EARLIER.text(), List.of(), v -> RingEdits.moveState(text, a, k, k - 1)));
        }
        if (k < n - 1) {
            actions.add(new Action(PanelMsg.DIAGRAM_LATER.text(), List.of(), v -> RingEdits.moveState(text, a, k, k + 1)));
        }
        if (n > 1) {
            actions.add(new Action(PanelMsg.DIAGRAM_REMOVE.text(), List.of(), v -> RingEdits.removeState(text, a, k)));
        }
        return new Target(PanelMsg.DIAGRAM_STATE_TITLE.text(k, a.name(), arc.state()), fields, k,
                to -> RingEdits.moveState(text, a, k, to), actions);
    }
}
