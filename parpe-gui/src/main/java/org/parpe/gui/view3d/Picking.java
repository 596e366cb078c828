package org.parpe.gui.view3d;

import org.eclipse.swt.graphics.Point;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.geom.Vec3;

/**
 * Finds the module under a point of the 3D view, with the camera of the last frame drawn: each
 * piece of a module is projected as a disc of its size, and of the discs under the point the one
 * nearest the eye wins.
 */
final class Picking {
    /** A click this close to a small piece still picks it, pixels. */
    private static final double MIN_RADIUS_PX = 8;
    private static final double NEAR = SceneRenderer.NEAR_VIEW;

    private Picking() {
    }

    static int moduleAt(Camera cam, SimSnapshot snap, int x, int y) {
        SimBody b = bodyAt(cam, snap, x, y, true);
        return b == null ? -1 : b.moduleId();
    }

    /** The piece under (x, y) nearest the eye ({@code modulesOnly}: of the active modules), or null. */
    static SimBody bodyAt(Camera cam, SimSnapshot snap, int x, int y, boolean modulesOnly) {
        if (snap == null) {
            return null;
        }
        double[] c = new double[3];
        SimBody best = null;
        double bestDepth = Double.POSITIVE_INFINITY;
        for (SimBody b : snap.bodies()) {
            if (modulesOnly && b.moduleId() < 0) {
                continue;
            }
            Vec3 p = b.position();
            cam.toCamera(p.x(), p.y(), p.z(), c);
            if (c[2] < NEAR) {
                continue;
            }
            double r = Math.max(MIN_RADIUS_PX, extent(b.shape()) * cam.scale(c[2]));
            double dx = cam.screenX(c[0], c[2]) - x;
            double dy = cam.screenY(c[1], c[2]) - y;
            if (dx * dx + dy * dy <= r * r && c[2] < bestDepth) {
                bestDepth = c[2];
                best = b;
            }
        }
        return best;
    }

    /** The screen point of the first piece of module {@code id} (its segment), or null. */
    static Point screenPoint(Camera cam, SimSnapshot snap, int id) {
        if (snap == null) {
            return null;
        }
        double[] c = new double[3];
        for (SimBody b : snap.bodies()) {
            if (b.moduleId() != id) {
                continue;
            }
            Vec3 p = b.position();
            cam.toCamera(p.x(), p.y(), p.z(), c);
            if (c[2] >= NEAR) {
                return new Point((int) Math.round(cam.screenX(c[0], c[2])), (int) Math.round(cam.screenY(c[1], c[2])));
            }
        }
        return null;
    }

    private static double extent(BodyShape shape) {
        if (shape instanceof BodyShape.Box box) {
            return Math.min(box.hx(), Math.min(box.hy(), box.hz())) * 0.5 + Math.max(box.hx(), Math.max(box.hy(), box.hz())) * 0.5;
        }
        if (shape instanceof BodyShape.Cylinder cyl) {
            return Math.max(cyl.radius(), cyl.length() / 2);
        }
        return ((BodyShape.Sphere) shape).radius();
    }
}
