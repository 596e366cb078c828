package org.parpe.gui.view3d;

import java.util.Set;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Composite;
import org.parpe.gui.text.PanelMsg;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.geom.Vec3;

/**
 * What a camera on one module sees, as the paper's snake carried a CCD camera through the rubble:
 * the scene of the latest snapshot drawn from the front face of the module's turning half,
 * looking along its x axis (away from the module's first plate). Pulls snapshots like
 * {@link View3D}; the UI thread redraws it.
 */
public final class ModuleCameraView {
    /** How far ahead of the lens the camera's target lies, m (only fixes the orientation). */
    private static final double AHEAD = 0.2;

    private final Canvas canvas;
    private final Camera camera = new Camera();
    /** The lens's near plane, m: a module's camera sees what it touches (the view's 2 cm would hide it). */
    static final double NEAR = 0.002;

    private final SceneRenderer renderer = new SceneRenderer(NEAR);
    private Supplier<SimSnapshot> source = () -> null;
    private int module;

    /** Creates the view in {@code parent}. */
    public ModuleCameraView(Composite parent) {
        canvas = new Canvas(parent, SWT.DOUBLE_BUFFERED | SWT.NO_BACKGROUND);
        canvas.addListener(SWT.Paint, e -> {
            Rectangle r = canvas.getClientArea();
            render(e.gc, r.width, r.height);
        });
    }

    /** The canvas. */
    public Canvas control() {
        return canvas;
    }

    /** Where snapshots come from (called on the UI thread, may return null). */
    public void setSource(Supplier<SimSnapshot> source) {
        this.source = source;
    }

    /** The module whose camera is shown. */
    public void setModule(int id) {
        module = id;
        canvas.redraw();
    }

    /** The module whose camera is shown. */
    public int module() {
        return module;
    }

    /** Draws one frame from the module's camera on {@code gc}. */
    public void render(GC gc, int width, int height) {
        SimSnapshot snap = source.get();
        SimBody lens = snap == null ? null : lens(snap, module);
        gc.setAntialias(SWT.ON);
        if (lens != null) {
            aim(lens);
            renderer.draw(gc, camera, snap, new SceneRenderer.Style(Set.of(), false), width, height);
        } else {
            renderer.draw(gc, camera, null, new SceneRenderer.Style(Set.of(), false), width, height);
        }
        gc.setAntialias(SWT.DEFAULT);
        gc.setForeground(renderer.color(0x2A3648));
        gc.drawText((lens == null ? PanelMsg.CAMERA_NO_MODULE : PanelMsg.CAMERA_ON_MODULE).text(module), 8, 6, true);
    }

    /** The turning half of module {@code id}, or null. */
    static SimBody lens(SimSnapshot snap, int id) {
        for (SimBody b : snap.bodies()) {
            if (b.moduleId() == id && b.kind() == PartKind.SEGMENT_ARM) {
                return b;
            }
        }
        return null;
    }

    /** Puts the eye on the front face of {@code lens}, looking along its x axis. */
    private void aim(SimBody lens) {
        Vec3 f = lens.rotation().axis(0);
        double front = lens.shape() instanceof BodyShape.Box box ? box.hx() + 0.002 : 0.03;
        Vec3 p = lens.position();
        double ex = p.x() + front * f.x();
        double ey = p.y() + front * f.y();
        double ez = p.z() + front * f.z();
        camera.lookAt(ex + AHEAD * f.x(), ey + AHEAD * f.y(), ez + AHEAD * f.z());
        camera.distance = AHEAD;
        camera.yaw = Math.atan2(-f.y(), -f.x());
        camera.pitch = Math.asin(Math.max(-1, Math.min(1, -f.z())));
    }
}
