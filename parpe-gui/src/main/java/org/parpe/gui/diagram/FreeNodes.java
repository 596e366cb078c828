package org.parpe.gui.diagram;

import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Event;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diagram.Scene;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.diagram.Workbench;
import org.parpe.gui.text.PanelMsg;

/**
 * Dragging the free nodes of the workbench under the program view and the lanes
 * ({@link Projection.Free}). Put down on the workbench, a node stays where it was put: its
 * place is layout only, kept beside the script ({@link PlacesBeside}), and the text does not
 * change (so there is nothing to undo; dragging it back is). Put down on the drawing above, it
 * becomes part of the script through the view's drop edit (a {@code <main>} entry, an
 * instance), one Undo step like every other diagram edit. UI thread only.
 */
final class FreeNodes {
    /** The names the places of each view's free nodes are kept under. */
    static final String PROGRAM = "program";
    static final String LANES = "lanes";

    private final DiagramPane pane;
    private final SceneCanvas canvas;
    private final PlacesBeside places;
    private Workbench.Placed held;
    /** Where in the held node the pointer took it, in scene units. */
    private double[] grip;
    private Point from;
    private boolean moved;

    FreeNodes(DiagramPane pane, SceneCanvas canvas) {
        this.pane = pane;
        this.canvas = canvas;
        this.places = new PlacesBeside(pane::say);
        canvas.control().addListener(SWT.MouseDown, this::down);
        canvas.control().addListener(SWT.MouseMove, this::move);
        canvas.control().addListener(SWT.MouseUp, this::up);
    }

    /** The free node named {@code name} as drawn now, or {@code null}. */
    Workbench.Placed node(String name) {
        Projection.Free f = free();
        return f == null ? null : f.bench().placed().stream().filter(n -> n.node().name().equals(name)).findFirst().orElse(null);
    }

    /** Where on the canvas the middle of free node {@code name} is drawn, or {@code null}. */
    Point where(String name) {
        Workbench.Placed n = node(name);
        return n == null ? null : canvas.toCanvas(n.sceneX() + n.w() / 2, n.sceneY() + n.h() / 2);
    }

    /** Where free node {@code name} is on its workbench ({@code x, y}), or {@code null} when it is not drawn. */
    double[] at(String name) {
        Workbench.Placed n = node(name);
        return n == null ? null : new double[] {n.x(), n.y()};
    }

    /** The places of the free nodes, kept beside the script. */
    PlacesBeside places() {
        return places;
    }

    private Projection.Free free() {
        return pane.shown() == null ? null : pane.shown().free();
    }

    private void down(Event e) {
        Projection.Free f = free();
        held = null;
        if (e.button != 1 || f == null) {
            return;
        }
        double[] p = canvas.toScene(e.x, e.y);
        held = f.bench().at(p[0], p[1]);
        if (held != null) {
            grip = new double[] {p[0] - held.sceneX(), p[1] - held.sceneY()};
            from = new Point(e.x, e.y);
            moved = false;
        }
    }

    private void move(Event e) {
        if (held == null || !moved && Math.abs(e.x - from.x) + Math.abs(e.y - from.y) <= 3) {
            return;
        }
        moved = true;
        double[] p = canvas.toScene(e.x, e.y);
        double x = p[0] - grip[0];
        double y = p[1] - grip[1];
        canvas.overlay(List.of(new Scene.Rect(x, y, held.w(), held.h(), Scene.NONE, SceneCanvas.SELECTION, 2, null),
                new Scene.Text(x + 12, y + 24, held.node().name(), 13, -1, SceneCanvas.SELECTION, true)));
        pane.say(free().hint());
    }

    private void up(Event e) {
        Workbench.Placed n = held;
        held = null;
        if (n == null || !moved) {
            return;
        }
        canvas.overlay(List.of());
        Projection.Free f = free();
        double[] p = canvas.toScene(e.x, e.y);
        if (p[1] < f.bench().top()) {
            SourcePos on = canvas.hit(p[0], p[1]);
            TextEdit edit;
            try {
                edit = f.drop().at(n.node().name(), p[1], on);
            } catch (IllegalArgumentException x) {
                pane.say(x.getMessage());
                return;
            }
            if (edit == null) {
                pane.say(PanelMsg.DIAGRAM_NOT_A_PLACE.text(n.node().name(), f.hint()));
            } else if (!pane.current()) {
                pane.say(PanelMsg.DIAGRAM_CHANGED.text());
            } else {
                pane.link().apply(edit);
            }
            return;
        }
        double[] at = f.bench().clamp(p[0] - grip[0], p[1] - grip[1], n.w(), n.h());
        places.put(f.view(), n.node().name(), at[0], at[1],
                f.bench().placed().stream().map(m -> m.node().name()).toList());
        pane.relayout();
    }
}
