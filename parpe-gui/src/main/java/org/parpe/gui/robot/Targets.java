package org.parpe.gui.robot;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Point;
import org.parpe.gui.view3d.BuildLayer;
import org.parpe.gui.view3d.View3D;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.build.BuildPlate;

/**
 * The Robot tab's layer on the 3D view: each free plate drawn as a disc on its face (the one
 * selected yellow, a second one for Connect orange, a plate that can latch ringed in purple),
 * parts painted by the script's groups, the part selected and parts at fault marked, the part
 * being previewed translucent; clicks pick plates first, then parts.
 */
final class Targets implements BuildLayer {
    /** The disc's radius, m (a G1 plate is 5 cm square). */
    static final double DISC = 0.018;
    private static final int SIDES = 16;
    /** A click this close to a disc's centre picks it, pixels at least. */
    private static final double MIN_HIT_PX = 7;
    static final int SELECTED = 0xFFD23F;
    private static final int SECOND = 0xFF8C42;
    private static final int FREE = 0x4FC3F7;
    private static final int LATCH = 0xB23CC8;
    static final int FAULT = 0xD93B3B;

    /** What a click picked. */
    interface Picked {
        /** A free plate ({@code adding}: Ctrl held, the second plate for Connect; {@code twice}: double click, Place). */
        void plate(BuildPlate p, boolean adding, boolean twice);

        /** A part (its name). */
        void part(String name);

        /** Nothing: the selection is cleared. */
        void nothing();
    }

    private final View3D view;
    private final Picked picked;
    private final Map<Integer, Color> colours = new HashMap<>();
    List<BuildPlate> plates = List.of();
    BuildPlate first;
    BuildPlate second;
    String part;
    List<SimBody> ghosts = List.of();
    /** Colours of parts (by name): the script's groups, parts at fault. */
    Map<String, Integer> paint = Map.of();
    /** Parts whose plates can latch (their modules declare the latch actuator). */
    Set<String> latching = Set.of();

    Targets(View3D view, Picked picked) {
        this.view = view;
        this.picked = picked;
        view.control().addListener(SWT.Dispose, e -> colours.values().forEach(Color::dispose));
    }

    @Override
    public boolean clicked(int x, int y, int stateMask, boolean twice) {
        BuildPlate p = plateAt(x, y);
        if (p != null) {
            picked.plate(p, (stateMask & SWT.MOD1) != 0, twice);
            return true;
        }
        String name = view.partAt(x, y);
        if (name != null) {
            picked.part(name);
            return true;
        }
        if (!twice) {
            picked.nothing();
        }
        return false;
    }

    @Override
    public int colour(SimBody body) {
        if (body.part().equals(part)) {
            return SELECTED;
        }
        Integer c = paint.get(body.part());
        return c == null ? -1 : c;
    }

    @Override
    public List<SimBody> ghosts() {
        return ghosts;
    }

    @Override
    public void decorate(GC gc) {
        double[] eye = view.eye();
        for (BuildPlate p : plates) {
            boolean facing = facing(p, eye);
            int rgb = same(p, first) ? SELECTED : same(p, second) ? SECOND : FREE;
            int[] poly = disc(p);
            if (poly == null) {
                continue;
            }
            gc.setAlpha(facing || rgb != FREE ? 230 : 70);
            gc.setBackground(colour(rgb));
            gc.fillPolygon(poly);
            gc.setForeground(colour(latching.contains(p.part()) ? LATCH : 0x1A2A44));
            gc.setLineWidth(latching.contains(p.part()) ? 3 : 1);
            gc.drawPolygon(poly);
        }
        gc.setAlpha(255);
        gc.setLineWidth(1);
    }

    /** The free plate whose disc is under (x, y), the nearest to it of those facing the eye first, or null. */
    BuildPlate plateAt(int x, int y) {
        double[] eye = view.eye();
        BuildPlate best = null;
        double bestScore = Double.POSITIVE_INFINITY;
        for (BuildPlate p : plates) {
            double[] s = view.project(lifted(p));
            if (s == null) {
                continue;
            }
            double r = Math.max(MIN_HIT_PX, DISC * s[2]);
            double dx = s[0] - x;
            double dy = s[1] - y;
            if (dx * dx + dy * dy > r * r) {
                continue;
            }
            // the disc whose centre is nearest the click, one facing the eye before one seen through the part
            double score = Math.sqrt(dx * dx + dy * dy) + (facing(p, eye) ? 0 : 1e6);
            if (score < bestScore) {
                bestScore = score;
                best = p;
            }
        }
        return best;
    }

    /**
     * Where plate {@code part.plate}'s disc appears on the canvas, or null when it is not free,
     * not in sight, or seen from behind (through its part: turn the view to click it).
     */
    Point screenPoint(String partName, int plate) {
        for (BuildPlate p : plates) {
            if (p.part().equals(partName) && p.plate() == plate && facing(p, view.eye())) {
                double[] s = view.project(lifted(p));
                return s == null ? null : new Point((int) Math.round(s[0]), (int) Math.round(s[1]));
            }
        }
        return null;
    }

    static boolean same(BuildPlate a, BuildPlate b) {
        return a != null && b != null && a.part().equals(b.part()) && a.plate() == b.plate();
    }

    /** The disc's outline on the canvas (a polygon), or null when part of it is behind the eye. */
    private int[] disc(BuildPlate p) {
        Vec3 c = lifted(p);
        Vec3 u = p.up();
        Vec3 n = p.normal();
        Vec3 v = new Vec3(n.y() * u.z() - n.z() * u.y(), n.z() * u.x() - n.x() * u.z(), n.x() * u.y() - n.y() * u.x());
        int[] out = new int[2 * SIDES];
        for (int k = 0; k < SIDES; k++) {
            double a = 2 * Math.PI * k / SIDES;
            double cu = DISC * Math.cos(a);
            double sv = DISC * Math.sin(a);
            double[] s = view.project(new Vec3(c.x() + cu * u.x() + sv * v.x(), c.y() + cu * u.y() + sv * v.y(),
                    c.z() + cu * u.z() + sv * v.z()));
            if (s == null) {
                return null;
            }
            out[2 * k] = (int) Math.round(s[0]);
            out[2 * k + 1] = (int) Math.round(s[1]);
        }
        return out;
    }

    /** The plate's centre a millimetre out of its face, so that the disc is drawn on it, not in it. */
    private static Vec3 lifted(BuildPlate p) {
        Vec3 c = p.centre();
        Vec3 n = p.normal();
        return new Vec3(c.x() + 0.001 * n.x(), c.y() + 0.001 * n.y(), c.z() + 0.001 * n.z());
    }

    private static boolean facing(BuildPlate p, double[] eye) {
        Vec3 c = p.centre();
        Vec3 n = p.normal();
        return (eye[0] - c.x()) * n.x() + (eye[1] - c.y()) * n.y() + (eye[2] - c.z()) * n.z() > 0;
    }

    private Color colour(int rgb) {
        return colours.computeIfAbsent(rgb, k -> new Color((k >> 16) & 0xFF, (k >> 8) & 0xFF, k & 0xFF));
    }
}
