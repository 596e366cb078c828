package org.parpe.gui.view3d;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.geom.Vec3;

/**
 * Draws a {@link SimSnapshot} with a {@link Camera} on a GC: every box, cylinder and sphere is
 * cut into flat-shaded faces in camera space, back faces are culled, and the rest are painted
 * far to near (painter's algorithm) over a ground grid and soft ground shadows.
 */
final class SceneRenderer {
    /** The orbiting view's near plane, m: nothing closer to the eye is drawn. */
    static final double NEAR_VIEW = 0.02;
    private static final int CYL_SIDES = 14;
    private static final double[] LIGHT = normalized(0.35, -0.45, 0.82);

    private final FaceBuffer faces = new FaceBuffer();
    private final GridPainter grid = new GridPainter();
    private final Map<Integer, Color> colors = new HashMap<>();
    private final double[] tmp = new double[3];
    private final double[] corners = new double[3 * 2 * CYL_SIDES];
    private final double[] inCamera = new double[3 * 2 * CYL_SIDES];
    private final double[] clipped = new double[3 * (2 * CYL_SIDES + 1)];
    private final double near;

    /** A renderer for the orbiting view (near plane {@link #NEAR_VIEW}). */
    SceneRenderer() {
        this(NEAR_VIEW);
    }

    /**
     * A renderer whose near plane is {@code near} m from the eye: a camera carried on a module
     * needs a short one, or a wall it touches (the slot machine at 1.6 cm) vanishes.
     */
    SceneRenderer(double near) {
        this.near = near;
    }

    /**
     * Which modules to highlight, whether to label module IDs, the module a drag would turn (−1:
     * none), and a builder's colour for each piece (null, or −1 from it: the usual colour).
     */
    record Style(Set<Integer> highlighted, boolean labels, int hover, java.util.function.ToIntFunction<SimBody> paint) {
        Style(Set<Integer> highlighted, boolean labels) {
            this(highlighted, labels, -1, null);
        }

        Style(Set<Integer> highlighted, boolean labels, int hover) {
            this(highlighted, labels, hover, null);
        }

        int colour(SimBody b) {
            int own = paint == null ? -1 : paint.applyAsInt(b);
            return own >= 0 ? own : b.moduleId() >= 0 && b.moduleId() == hover ? HOVER : baseColor(b, highlighted);
        }
    }

    void draw(GC gc, Camera cam, SimSnapshot snap, Style style, int width, int height) {
        cam.update(width, height);
        grid.draw(gc, cam, width, height);
        if (snap == null) {
            return;
        }
        gc.setAlpha(55);
        gc.setBackground(color(0x202020));
        for (SimBody b : snap.bodies()) {
            shadow(gc, cam, b);
        }
        gc.setAlpha(255);
        faces.clear();
        for (SimBody b : snap.scenery()) {
            solid(cam, b, baseColor(b, style.highlighted()));
        }
        for (SimBody b : snap.bodies()) {
            solid(cam, b, style.colour(b));
        }
        paintFaces(gc);
        if (style.labels()) {
            labels(gc, cam, snap, style.highlighted());
        }
    }

    /** The colour of a piece not yet placed (drawn translucent over the robot). */
    private static final int GHOST = 0x3FBF6A;

    /** Pieces not yet placed (a builder's preview), translucent over what is drawn. */
    void ghosts(GC gc, Camera cam, java.util.List<SimBody> bodies) {
        if (bodies.isEmpty()) {
            return;
        }
        faces.clear();
        for (SimBody b : bodies) {
            solid(cam, b, GHOST);
        }
        gc.setAlpha(140);
        paintFaces(gc);
        gc.setAlpha(255);
    }

    /** The colour of the module a drag would bend (the mouse is over it). */
    private static final int HOVER = 0xFFD23F;

    /** TrackRobot's trail: the path of the centre of mass on the floor since the run started. */
    void trail(GC gc, Camera cam, java.util.List<Vec3> points) {
        if (points.size() < 2) {
            return;
        }
        gc.setForeground(color(0xE0602A));
        gc.setLineWidth(2);
        int[] xy = new int[points.size() * 2];
        int n = 0;
        for (Vec3 p : points) {
            cam.toCamera(p.x(), p.y(), 0.002, tmp);
            if (tmp[2] < near) {
                continue;
            }
            xy[n++] = (int) cam.screenX(tmp[0], tmp[2]);
            xy[n++] = (int) cam.screenY(tmp[1], tmp[2]);
        }
        if (n >= 4) {
            gc.drawPolyline(java.util.Arrays.copyOf(xy, n));
        }
        gc.setLineWidth(1);
    }

    /** Adds the faces of {@code b} in colour {@code rgb}. */
    private void solid(Camera cam, SimBody b, int rgb) {
        BodyShape shape = b.shape();
        if (shape instanceof BodyShape.Box box) {
            box(cam, b.position(), b.rotation(), box, rgb);
        } else if (shape instanceof BodyShape.Cylinder c) {
            cylinder(cam, b.position(), b.rotation(), c, rgb);
        } else if (shape instanceof BodyShape.Sphere s) {
            sphere(cam, b.position(), s, rgb);
        }
    }

    private void paintFaces(GC gc) {
        Integer[] order = faces.farToNear();
        boolean edges = order.length < 3000;
        for (Integer i : order) {
            gc.setBackground(color(faces.rgb[i]));
            if (faces.radius[i] > 0) {
                int[] p = faces.points[i];
                int r = faces.radius[i];
                gc.fillOval(p[0] - r, p[1] - r, 2 * r, 2 * r);
                continue;
            }
            gc.fillPolygon(faces.points[i]);
            if (edges) {
                gc.setForeground(color(darker(faces.rgb[i], 0.72)));
                gc.drawPolygon(faces.points[i]);
            }
        }
    }

    private void box(Camera cam, Vec3 pos, Mat3 r, BodyShape.Box box, int rgb) {
        for (int k = 0; k < 8; k++) {
            double lx = (k & 1) == 0 ? -box.hx() : box.hx();
            double ly = (k & 2) == 0 ? -box.hy() : box.hy();
            double lz = (k & 4) == 0 ? -box.hz() : box.hz();
            world(pos, r, lx, ly, lz, k);
        }
        // Faces as corner indices (bit 0: x, bit 1: y, bit 2: z) with the local normal axis and sign.
        face(cam, rgb, r, 0, -1, 0, 4, 6, 2);
        face(cam, rgb, r, 0, 1, 1, 3, 7, 5);
        face(cam, rgb, r, 1, -1, 0, 1, 5, 4);
        face(cam, rgb, r, 1, 1, 2, 6, 7, 3);
        face(cam, rgb, r, 2, -1, 0, 2, 3, 1);
        face(cam, rgb, r, 2, 1, 4, 5, 7, 6);
    }

    private void cylinder(Camera cam, Vec3 pos, Mat3 r, BodyShape.Cylinder c, int rgb) {
        double h = c.length() / 2;
        for (int k = 0; k < CYL_SIDES; k++) {
            double a = 2 * Math.PI * k / CYL_SIDES;
            double x = c.radius() * Math.cos(a);
            double y = c.radius() * Math.sin(a);
            world(pos, r, x, y, -h, k);
            world(pos, r, x, y, h, k + CYL_SIDES);
        }
        for (int k = 0; k < CYL_SIDES; k++) {
            int n = (k + 1) % CYL_SIDES;
            double a = 2 * Math.PI * (k + 0.5) / CYL_SIDES;
            double nx = r.m00() * Math.cos(a) + r.m01() * Math.sin(a);
            double ny = r.m10() * Math.cos(a) + r.m11() * Math.sin(a);
            double nz = r.m20() * Math.cos(a) + r.m21() * Math.sin(a);
            emit(cam, rgb, nx, ny, nz, k, n, n + CYL_SIDES, k + CYL_SIDES);
        }
        int[] bottom = new int[CYL_SIDES];
        int[] top = new int[CYL_SIDES];
        for (int k = 0; k < CYL_SIDES; k++) {
            bottom[k] = CYL_SIDES - 1 - k;
            top[k] = k + CYL_SIDES;
        }
        emit(cam, rgb, -r.m02(), -r.m12(), -r.m22(), bottom);
        emit(cam, rgb, r.m02(), r.m12(), r.m22(), top);
    }

    private void sphere(Camera cam, Vec3 pos, BodyShape.Sphere s, int rgb) {
        cam.toCamera(pos.x(), pos.y(), pos.z(), tmp);
        if (tmp[2] < near) {
            return;
        }
        int rad = (int) Math.max(1, Math.round(s.radius() * cam.scale(tmp[2])));
        faces.add(new int[] {(int) Math.round(cam.screenX(tmp[0], tmp[2])), (int) Math.round(cam.screenY(tmp[1], tmp[2]))},
                tmp[2], shade(rgb, 0, 0, 1), rad);
    }

    private void world(Vec3 p, Mat3 r, double x, double y, double z, int k) {
        corners[3 * k] = p.x() + r.m00() * x + r.m01() * y + r.m02() * z;
        corners[3 * k + 1] = p.y() + r.m10() * x + r.m11() * y + r.m12() * z;
        corners[3 * k + 2] = p.z() + r.m20() * x + r.m21() * y + r.m22() * z;
    }

    private void face(Camera cam, int rgb, Mat3 r, int axis, int sign, int... idx) {
        emit(cam, rgb, sign * r.get(0, axis), sign * r.get(1, axis), sign * r.get(2, axis), idx);
    }

    /**
     * Adds the face through the given corners if it faces the camera, cut at the near plane: the
     * part in front of the eye is drawn (a wall the camera nearly touches, seen at an angle, has
     * corners behind the eye and must not vanish whole).
     */
    private void emit(Camera cam, int rgb, double nx, double ny, double nz, int... idx) {
        double[] eye = cam.eye();
        int c0 = 3 * idx[0];
        if ((corners[c0] - eye[0]) * nx + (corners[c0 + 1] - eye[1]) * ny + (corners[c0 + 2] - eye[2]) * nz >= 0) {
            return;
        }
        int n = idx.length;
        for (int j = 0; j < n; j++) {
            int c = 3 * idx[j];
            cam.toCamera(corners[c], corners[c + 1], corners[c + 2], tmp);
            System.arraycopy(tmp, 0, inCamera, 3 * j, 3);
        }
        int m = 0; // Sutherland-Hodgman against the one plane z = near
        for (int j = 0; j < n; j++) {
            int a = 3 * j;
            int b = 3 * ((j + 1) % n);
            boolean aIn = inCamera[a + 2] >= near;
            boolean bIn = inCamera[b + 2] >= near;
            if (aIn) {
                System.arraycopy(inCamera, a, clipped, 3 * m++, 3);
            }
            if (aIn != bIn) {
                double t = (near - inCamera[a + 2]) / (inCamera[b + 2] - inCamera[a + 2]);
                for (int k = 0; k < 3; k++) {
                    clipped[3 * m + k] = inCamera[a + k] + t * (inCamera[b + k] - inCamera[a + k]);
                }
                m++;
            }
        }
        if (m < 3) {
            return;
        }
        int[] pts = new int[2 * m];
        double depth = 0;
        for (int j = 0; j < m; j++) {
            double z = Math.max(near, clipped[3 * j + 2]);
            pts[2 * j] = (int) Math.round(cam.screenX(clipped[3 * j], z));
            pts[2 * j + 1] = (int) Math.round(cam.screenY(clipped[3 * j + 1], z));
            depth += z;
        }
        faces.add(pts, depth / m, shade(rgb, nx, ny, nz), 0);
    }

    private void shadow(GC gc, Camera cam, SimBody b) {
        Vec3 p = b.position();
        double size = extent(b.shape());
        cam.toCamera(p.x(), p.y(), 0, tmp);
        if (tmp[2] < near || p.z() > 1.0) {
            return;
        }
        double px = size * cam.scale(tmp[2]) * 1.1;
        double py = px * Math.max(0.2, Math.sin(cam.pitch));
        gc.fillOval((int) (cam.screenX(tmp[0], tmp[2]) - px), (int) (cam.screenY(tmp[1], tmp[2]) - py),
                (int) (2 * px), (int) (2 * py));
    }

    private static double extent(BodyShape shape) {
        if (shape instanceof BodyShape.Box box) {
            return Math.max(box.hx(), Math.max(box.hy(), box.hz()));
        }
        if (shape instanceof BodyShape.Cylinder c) {
            return Math.max(c.radius(), c.length() / 2);
        }
        return ((BodyShape.Sphere) shape).radius();
    }

    /**
     * Module IDs over their segments. A label that would overlap one already drawn is left out
     * (on the centipede they ran into a blur): the highlighted modules' first, then the nearest
     * to the eye, so what is left out is far away or behind; hover or zoom in to see it.
     */
    private void labels(GC gc, Camera cam, SimSnapshot snap, Set<Integer> first) {
        java.util.List<Label> all = new java.util.ArrayList<>();
        for (SimBody b : snap.bodies()) {
            if (b.moduleId() < 0 || b.kind() != PartKind.SEGMENT_BASE) {
                continue;
            }
            Vec3 p = b.position();
            cam.toCamera(p.x(), p.y(), p.z(), tmp);
            if (tmp[2] < near) {
                continue;
            }
            String t = Integer.toString(b.moduleId());
            var ext = gc.textExtent(t);
            int x = (int) cam.screenX(tmp[0], tmp[2]) - ext.x / 2;
            int y = (int) cam.screenY(tmp[1], tmp[2]) - ext.y - 6;
            all.add(new Label(b.moduleId(), new org.eclipse.swt.graphics.Rectangle(x - 3, y - 1, ext.x + 6, ext.y + 2),
                    first.contains(b.moduleId()) ? -1 : tmp[2]));
        }
        all.sort(java.util.Comparator.comparingDouble(Label::depth));
        shownLabels = place(all);
        gc.setForeground(color(0xFFFFFF));
        gc.setBackground(color(0x1A2A44));
        for (Label l : shownLabels) {
            var r = l.box();
            gc.fillRoundRectangle(r.x, r.y, r.width, r.height, 6, 6);
            gc.drawText(Integer.toString(l.id()), r.x + 3, r.y + 1, true);
        }
    }

    /** A module ID's label: its box on the screen and its distance from the eye (−1: drawn first). */
    record Label(int id, org.eclipse.swt.graphics.Rectangle box, double depth) {
    }

    /** The labels drawn last (tests). */
    private java.util.List<Label> shownLabels = java.util.List.of();

    java.util.List<Label> shownLabels() {
        return shownLabels;
    }

    /** The labels of {@code ordered} that do not overlap one placed before them, in that order. */
    static java.util.List<Label> place(java.util.List<Label> ordered) {
        java.util.List<Label> out = new java.util.ArrayList<>();
        for (Label l : ordered) {
            if (out.stream().noneMatch(o -> o.box().intersects(l.box()))) {
                out.add(l);
            }
        }
        return out;
    }

    private static int baseColor(SimBody b, Set<Integer> highlighted) {
        boolean hot = b.moduleId() >= 0 && highlighted.contains(b.moduleId());
        return switch (b.kind()) {
            case SEGMENT_BASE -> hot ? 0xE07A1F : 0x3E6FB0;
            case SEGMENT_ARM -> hot ? 0xF2A046 : 0x6F9BD6;
            case NODE -> 0x8A8F99;
            case FOOT -> 0x4A4D55;
            case HUB -> 0xA7ACB5;
            case SCENERY -> 0xB9A88C;
            case OBJECT -> 0xD9B43B;
        };
    }

    private static int shade(int rgb, double nx, double ny, double nz) {
        double lambert = Math.max(0, nx * LIGHT[0] + ny * LIGHT[1] + nz * LIGHT[2]);
        return darker(rgb, 0.42 + 0.58 * lambert);
    }

    private static int darker(int rgb, double f) {
        int r = (int) Math.min(255, ((rgb >> 16) & 0xFF) * f);
        int g = (int) Math.min(255, ((rgb >> 8) & 0xFF) * f);
        int b = (int) Math.min(255, (rgb & 0xFF) * f);
        return (r << 16) | (g << 8) | b;
    }

    Color color(int rgb) {
        // Quantised so that the cache stays small however many shades a frame has.
        int key = rgb & 0xFCFCFC;
        return colors.computeIfAbsent(key, k -> new Color((k >> 16) & 0xFF, (k >> 8) & 0xFF, k & 0xFF));
    }

    private static double[] normalized(double x, double y, double z) {
        double l = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / l, y / l, z / l};
    }

    /** The faces of one frame, grown as needed and reused between frames. */
    private static final class FaceBuffer {
        int count;
        int[][] points = new int[512][];
        double[] depth = new double[512];
        int[] rgb = new int[512];
        int[] radius = new int[512];

        void clear() {
            count = 0;
        }

        void add(int[] pts, double d, int color, int rad) {
            if (count == depth.length) {
                int n = count * 2;
                points = Arrays.copyOf(points, n);
                depth = Arrays.copyOf(depth, n);
                rgb = Arrays.copyOf(rgb, n);
                radius = Arrays.copyOf(radius, n);
            }
            points[count] = pts;
            depth[count] = d;
            rgb[count] = color;
            radius[count] = rad;
            count++;
        }

        Integer[] farToNear() {
            Integer[] order = new Integer[count];
            for (int i = 0; i < count; i++) {
                order[i] = i;
            }
            Arrays.sort(order, (a, b) -> Double.compare(depth[b], depth[a]));
            return order;
        }
    }
}
