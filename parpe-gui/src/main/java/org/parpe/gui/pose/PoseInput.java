package org.parpe.gui.pose;

import java.util.Set;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Listener;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.view3d.View3D;
import org.parpe.sim.snapshot.SimSnapshot;

/**
 * What the Pose panel takes from outside its own widgets: while it is posing, the 3D view shows
 * the posed robot with the group highlighted, a drag on one of the group's modules turns its
 * joint, Ctrl+click picks modules; and Space captures. When the panel is hidden or a run is
 * going on, the view shows what it showed before (the run or the preview).
 */
final class PoseInput {
    private PoseInput() {
    }

    static void attach(PosePanel panel, PoseHost host) {
        View3D view = host.view();
        Supplier<SimSnapshot> base = view.source();
        view.setSource(() -> panel.posing() && panel.sim().ready() ? panel.sim().snapshot() : base.get());
        Supplier<Set<Integer>> highlight = view.highlighted();
        view.setHighlighted(() -> panel.posing() && panel.poses() != null ? panel.posedModules() : highlight.get());
        view.setJointDrag(new View3D.JointDrag() {
            @Override
            public boolean canTurn(int id) {
                return panel.posing() && panel.posingInSimulator() && panel.sliders().indexOf(id) >= 0;
            }

            @Override
            public void turn(int id, double degrees) {
                panel.sliders().set(id, panel.sliders().angle(id) + degrees);
            }

            @Override
            public void picked(int id) {
                if (panel.posing()) {
                    panel.pick(id);
                }
            }
        });
        Control box = panel.control();
        Listener space = e -> spaceKey(panel, box, e);
        box.getDisplay().addFilter(SWT.KeyDown, space);
        box.addListener(SWT.Dispose, e -> box.getDisplay().removeFilter(SWT.KeyDown, space));
    }

    /** Space captures while the panel is shown, unless the focus is where Space types or presses. */
    private static void spaceKey(PosePanel panel, Control box, Event e) {
        if (e.keyCode != ' ' || e.stateMask != 0 || box.isDisposed() || !box.isVisible() || !panel.posing()) {
            return;
        }
        Control focus = e.display.getFocusControl();
        if (focus instanceof StyledText || focus instanceof Text || focus instanceof Combo || focus instanceof Button) {
            return;
        }
        if (focus != null && focus.getShell() == box.getShell()) {
            panel.capture();
            e.doit = false;
        }
    }
}
