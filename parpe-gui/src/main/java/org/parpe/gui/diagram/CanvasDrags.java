package org.parpe.gui.diagram;

import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.dnd.DND;
import org.eclipse.swt.dnd.DropTarget;
import org.eclipse.swt.dnd.DropTargetAdapter;
import org.eclipse.swt.dnd.DropTargetEvent;
import org.eclipse.swt.dnd.TextTransfer;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Event;
import org.parpe.core.diagram.Layouts;
import org.parpe.core.diagram.Scene;
import org.parpe.core.lang.Numbers;
import org.parpe.gui.text.PanelMsg;

/**
 * Editing the script by dragging on the Diagram pane's drawing: a {@code <main>} entry onto
 * another's place, the phase wheel's hand to another phase (previewed while dragged), and a pose
 * from the Pose panel onto a state of the ring. Each drop is one edit of the text, one Undo step,
 * through the pane. UI thread only.
 */
final class CanvasDrags {
    private final DiagramPane pane;
    private final SceneCanvas canvas;
    private Point dragFrom;
    private Projection.Target dragged;
    private boolean posesTaken;
    /** The phase wheel's hand and ticks where the drag going on would put them. */
    private List<Scene.Shape> preview = List.of();

    CanvasDrags(DiagramPane pane, SceneCanvas canvas) {
        this.pane = pane;
        this.canvas = canvas;
        canvas.control().addListener(SWT.MouseDown, this::down);
        canvas.control().addListener(SWT.MouseMove, this::move);
        canvas.control().addListener(SWT.MouseUp, this::up);
    }

    private void down(Event e) {
        dragged = e.button == 1 ? movable(e.x, e.y) : null;
        dragFrom = e.button == 1 && (wheel() != null || dragged != null) ? new Point(e.x, e.y) : null;
    }

    private void move(Event e) {
        if (dragFrom != null && dragged(e.x, e.y)) {
            if (wheel() != null) {
                previewPhase(phaseAt(e.x, e.y));
            } else {
                pane.hint(PanelMsg.DIAGRAM_RELEASE_ENTRY.text());
            }
        }
    }

    private void up(Event e) {
        if (dragFrom != null && dragged(e.x, e.y)) {
            if (wheel() != null) {
                dropPhase(e.x, e.y);
            } else {
                dropEntry(dragged, movable(e.x, e.y));
            }
        }
        dragFrom = null;
        if (!preview.isEmpty()) {
            preview = List.of();
            pane.repaintOverlay();
        }
    }

    /** The node at canvas pixel {@code x, y} if it can be moved by dragging, else {@code null}. */
    private Projection.Target movable(int x, int y) {
        Projection shown = pane.shown();
        if (shown == null) {
            return null;
        }
        double[] p = canvas.toScene(x, y);
        Projection.Target t = shown.targets().get(canvas.hit(p[0], p[1]));
        return t != null && t.moveTo() != null ? t : null;
    }

    /** An entry was dragged onto another: move it to that one's place (one Undo step). */
    private void dropEntry(Projection.Target from, Projection.Target onto) {
        if (from == null || onto == null || from.index() == onto.index()) {
            return;
        }
        if (!pane.current()) {
            pane.say(PanelMsg.DIAGRAM_CHANGED.text());
            return;
        }
        pane.link().apply(from.moveTo().apply(onto.index()));
    }

    /** The wheel's circle (centre and radius, in scene units) while a phase wheel is shown, else {@code null}. */
    private double[] wheel() {
        Projection shown = pane.shown();
        return shown == null || shown.wheel() == null || shown.scene() == null ? null : shown.index().wheelCircle();
    }

    private boolean dragged(int x, int y) {
        return Math.abs(x - dragFrom.x) + Math.abs(y - dragFrom.y) > 3;
    }

    /**
     * The phase that puts position 1's tick at canvas pixel {@code x, y}: its angle on the wheel
     * less the offset, in [0, 1) (in (−1, 0] when the phase was negative), to 0.01 of a cycle.
     */
    private double phaseAt(int x, int y) {
        double[] c = wheel();
        double[] p = canvas.toScene(x, y);
        double f = Math.atan2(p[0] - c[0], -(p[1] - c[1])) / (2 * Math.PI);
        var w = pane.shown().wheel();
        double phase = f - w.offset();
        phase -= Math.floor(phase);
        if (w.phase() < 0 && phase > 0) {
            phase -= 1;
        }
        return Math.round(phase * 100) / 100.0;
    }

    /** While the hand is dragged: the hand and the ticks where {@code phase} puts them, and the delays it gives, in words. */
    private void previewPhase(double phase) {
        var moved = pane.shown().wheel().withPhase(phase);
        preview = Layouts.wheelPreview(moved, pane.textScale());
        pane.repaintOverlay();
        StringBuilder delays = new StringBuilder();
        for (var t : moved.ticks().subList(0, Math.min(6, moved.ticks().size()))) {
            delays.append(delays.length() == 0 ? "" : ", ").append(Numbers.format(Math.round(t.delay() * 100) / 100.0));
        }
        pane.hint(PanelMsg.DIAGRAM_RELEASE_PHASE.text(Numbers.format(phase),
                delays + (moved.ticks().size() > 6 ? ", \u2026" : "")));
    }

    /** The wheel's hand and ticks drawn where the drag going on would put them (empty while none is). */
    List<Scene.Shape> preview() {
        return preview;
    }

    /** A drag on the phase wheel ended at {@code x, y}: write the phase it sets. */
    private void dropPhase(int x, int y) {
        Projection shown = pane.shown();
        Projection.Target t = shown.targets().get(shown.wheel().pos());
        if (t == null) {
            pane.say(PanelMsg.DIAGRAM_INSTANCE_ELSEWHERE.text());
            return;
        }
        String value = Numbers.format(phaseAt(x, y));
        for (Projection.Field f : t.fields()) {
            if (f.name().equals("phase")) {
                pane.link().write(f, value);
            }
        }
    }

    /** Where on the canvas the phase wheel's point at fraction {@code f} of a turn is, or {@code null}. */
    Point onWheel(double f) {
        double[] c = wheel();
        if (c == null) {
            return null;
        }
        double[] p = Scene.onCircle(c[0], c[1], c[2], f);
        return canvas.toCanvas(p[0], p[1]);
    }

    /** Poses dropped on the canvas (text: the Pose panel's angles) go to the state there; once. */
    void takePoses() {
        if (posesTaken) {
            return;
        }
        posesTaken = true;
        DropTarget drop = new DropTarget(canvas.control(), DND.DROP_COPY | DND.DROP_DEFAULT);
        drop.setTransfer(TextTransfer.getInstance());
        drop.addDropListener(new DropTargetAdapter() {
            @Override
            public void drop(DropTargetEvent e) {
                Point p = canvas.control().toControl(e.x, e.y);
                dropPose(p.x, p.y, (String) e.data);
            }
        });
    }

    /** Text {@code angles} was dropped at canvas pixel {@code x, y}: the state there takes them as its angles. */
    void dropPose(int x, int y, String angles) {
        Projection shown = pane.shown();
        double[] p = canvas.toScene(x, y);
        Projection.Target t = shown == null ? null : shown.targets().get(canvas.hit(p[0], p[1]));
        Projection.Field f = t == null ? null : t.fields().stream().filter(g -> g.name().equals("angles")).findFirst().orElse(null);
        if (f == null) {
            pane.say(PanelMsg.DIAGRAM_DROP_POSE.text());
            return;
        }
        pane.link().act(new Projection.Action(PanelMsg.DIAGRAM_USE_POSE.text(), List.of(), v -> f.edit().apply(EditRow.usable(angles))),
                List.of());
    }

}
