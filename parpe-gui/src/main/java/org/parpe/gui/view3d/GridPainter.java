package org.parpe.gui.view3d;

import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;

/**
 * The sky and the ground grid ({@code z = 0}) around the camera target, with lines clipped at
 * the near plane and a spacing that grows with the viewing distance.
 */
final class GridPainter {
    private static final double NEAR = SceneRenderer.NEAR_VIEW;
    private static final Color SKY_TOP = new Color(0xE9, 0xEF, 0xF7);
    private static final Color SKY_BOTTOM = new Color(0xC9, 0xD4, 0xE3);
    private static final Color LINE = new Color(0xA9, 0xB4, 0xC4);
    private static final Color MAJOR = new Color(0x8A, 0x97, 0xAA);
    private static final Color X_AXIS = new Color(0xC8, 0x50, 0x50);
    private static final Color Y_AXIS = new Color(0x4C, 0x9A, 0x5A);

    private final double[] a = new double[3];
    private final double[] b = new double[3];

    void draw(GC gc, Camera cam, int width, int height) {
        gc.setForeground(SKY_TOP);
        gc.setBackground(SKY_BOTTOM);
        gc.fillGradientRectangle(0, 0, width, height, true);
        double step = cam.distance() < 2.5 ? 0.1 : cam.distance() < 12 ? 0.5 : 2.0;
        int n = 24;
        double cx = Math.round(cam.target[0] / step) * step;
        double cy = Math.round(cam.target[1] / step) * step;
        double half = n * step;
        for (int i = -n; i <= n; i++) {
            double x = cx + i * step;
            double y = cy + i * step;
            boolean majorX = Math.abs(Math.round(x / step) % 5) == 0;
            boolean majorY = Math.abs(Math.round(y / step) % 5) == 0;
            gc.setForeground(Math.abs(x) < step / 2 ? Y_AXIS : majorX ? MAJOR : LINE);
            line(gc, cam, x, cy - half, x, cy + half);
            gc.setForeground(Math.abs(y) < step / 2 ? X_AXIS : majorY ? MAJOR : LINE);
            line(gc, cam, cx - half, y, cx + half, y);
        }
    }

    private void line(GC gc, Camera cam, double x0, double y0, double x1, double y1) {
        cam.toCamera(x0, y0, 0, a);
        cam.toCamera(x1, y1, 0, b);
        if (a[2] < NEAR && b[2] < NEAR) {
            return;
        }
        if (a[2] < NEAR) {
            clip(a, b);
        } else if (b[2] < NEAR) {
            clip(b, a);
        }
        gc.drawLine((int) cam.screenX(a[0], a[2]), (int) cam.screenY(a[1], a[2]),
                (int) cam.screenX(b[0], b[2]), (int) cam.screenY(b[1], b[2]));
    }

    /** Moves {@code p} (behind the near plane) along the segment to the near plane. */
    private static void clip(double[] p, double[] q) {
        double t = (NEAR - p[2]) / (q[2] - p[2]);
        for (int i = 0; i < 3; i++) {
            p[i] += (q[i] - p[i]) * t;
        }
    }
}
