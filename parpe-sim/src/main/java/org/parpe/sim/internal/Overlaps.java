package org.parpe.sim.internal;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.config.PartSpec;

/**
 * Finds parts of an assembled robot that overlap at the initial pose: two pieces that the
 * physics would make collide (not of one rigid cluster, not the two sides of one hinge) and
 * whose shapes go into each other deeper than {@link #TOLERANCE}. Such a robot cannot be built
 * and would fly apart in the simulator. Pieces are sorted into a grid first, so a robot of
 * thousands of parts is checked in time proportional to its size.
 */
final class Overlaps {
    /**
     * Deepest overlap let pass, m: a loop closes with its plates up to 3 mm apart and 3° turned
     * ({@link Assembly}), which can press a corner up to about 4 mm into its neighbour.
     */
    static final double TOLERANCE = 0.004;
    /** Most overlapping pairs of parts reported. */
    static final int MAX_REPORTED = 20;
    /** Edge of a grid cell, m: about the size of a piece. */
    private static final double CELL = 0.08;

    private final List<Assembly.PlacedPiece> pieces;
    private final Set<Long> jointed = new HashSet<>();

    private Overlaps(List<Assembly.PlacedPiece> pieces, List<Assembly.Hinge> hinges) {
        this.pieces = pieces;
        for (Assembly.Hinge h : hinges) {
            jointed.add(key(pieces.get(h.base()).cluster(), pieces.get(h.arm()).cluster()));
        }
    }

    /**
     * Reports pairs of overlapping parts to {@code diags}, the first {@link #MAX_REPORTED} in part
     * order (a robot folded onto itself overlaps everywhere; the first ones say what is wrong);
     * returns whether there was none.
     */
    static boolean check(List<Assembly.PlacedPiece> pieces, List<Assembly.Hinge> hinges, DiagnosticSink diags) {
        Overlaps o = new Overlaps(pieces, hinges);
        Map<PartSpec, Integer> order = new HashMap<>();
        for (Assembly.PlacedPiece p : pieces) {
            order.putIfAbsent(p.part(), order.size());
        }
        Map<Long, List<Integer>> grid = o.grid();
        Set<Long> reported = new HashSet<>();
        for (int a = 0; a < pieces.size(); a++) {
            for (int b : o.neighbours(a, grid)) {
                double depth = o.depth(a, b);
                PartSpec pa = pieces.get(a).part();
                PartSpec pb = pieces.get(b).part();
                if (depth <= TOLERANCE || !reported.add(key(order.get(pa), order.get(pb)))) {
                    continue;
                }
                if (reported.size() > MAX_REPORTED) {
                    diags.error(pb.pos(), org.parpe.core.text.Msg.MORE_OVERLAPS, MAX_REPORTED);
                    return false;
                }
                diags.error(pb.pos(), org.parpe.core.text.Msg.PARTS_OVERLAP, pb.name(), pa.name(),
                        pa.pos().line() > 0 ? org.parpe.core.text.Message.of(org.parpe.core.text.Msg.LINE_NOTE, pa.pos().line())
                                : org.parpe.core.text.Message.EMPTY,
                        String.format(Locale.ROOT, "%.1f", depth * 1000), String.format(Locale.ROOT, "%.0f", TOLERANCE * 1000));
            }
        }
        return reported.isEmpty();
    }

    /** Grid cell → the pieces whose bounding spheres reach into it, in ascending order. */
    private Map<Long, List<Integer>> grid() {
        Map<Long, List<Integer>> grid = new HashMap<>();
        for (int i = 0; i < pieces.size(); i++) {
            for (long c : cells(i)) {
                grid.computeIfAbsent(c, k -> new ArrayList<>()).add(i);
            }
        }
        return grid;
    }

    private List<Long> cells(int piece) {
        Assembly.PlacedPiece p = pieces.get(piece);
        Vec3 c = p.position();
        double r = Math.sqrt(3) * outer(p.def().shape());
        List<Long> out = new ArrayList<>();
        for (long x = cell(c.x() - r); x <= cell(c.x() + r); x++) {
            for (long y = cell(c.y() - r); y <= cell(c.y() + r); y++) {
                for (long z = cell(c.z() - r); z <= cell(c.z() + r); z++) {
                    // mixed by an odd multiplier (one to one): packed coordinates alone share their low
                    // bits along a chain, which piled a long robot's cells into a few hash buckets
                    out.add(((x & 0x1fffff) << 42 | (y & 0x1fffff) << 21 | (z & 0x1fffff)) * 0x9E3779B97F4A7C15L);
                }
            }
        }
        return out;
    }

    /** The pieces after {@code a} that share a cell with it and may collide with it, ascending. */
    private List<Integer> neighbours(int a, Map<Long, List<Integer>> grid) {
        java.util.TreeSet<Integer> out = new java.util.TreeSet<>();
        int ca = pieces.get(a).cluster();
        for (long c : cells(a)) {
            for (int b : grid.get(c)) {
                int cb = pieces.get(b).cluster();
                if (b > a && ca != cb && !jointed.contains(key(ca, cb))) {
                    out.add(b);
                }
            }
        }
        return new ArrayList<>(out);
    }

    private static long cell(double v) {
        return (long) Math.floor(v / CELL);
    }

    private static long key(int a, int b) {
        return (long) Math.min(a, b) << 32 | Math.max(a, b);
    }

    /**
     * How deep pieces {@code a} and {@code b} go into each other, m, by separating axes: the
     * least overlap of their projections on the candidate axes (the pieces' own axes, their
     * cross products and the line between their centres); 0 or less when they do not meet.
     */
    private double depth(int a, int b) {
        Assembly.PlacedPiece pa = pieces.get(a);
        Assembly.PlacedPiece pb = pieces.get(b);
        List<Vec3> axes = new ArrayList<>();
        List<Vec3> ownA = axes(pa);
        List<Vec3> ownB = axes(pb);
        axes.addAll(ownA);
        axes.addAll(ownB);
        for (Vec3 u : ownA) {
            for (Vec3 v : ownB) {
                axes.add(Geo.cross(u, v));
            }
        }
        Vec3 d = Geo.sub(pb.position(), pa.position());
        axes.add(d);
        double least = Double.POSITIVE_INFINITY;
        for (Vec3 axis : axes) {
            double len = axis.length();
            if (len < 1e-9) {
                continue;
            }
            Vec3 l = Geo.scale(axis, 1 / len);
            double overlap = radius(pa, l) + radius(pb, l) - Math.abs(Geo.dot(d, l));
            least = Math.min(least, overlap);
        }
        return least;
    }

    /** The directions that can separate a piece from others: a box's three axes, a cylinder's axis. */
    private static List<Vec3> axes(Assembly.PlacedPiece p) {
        Mat3 r = p.rotation();
        Vec3 x = new Vec3(r.m00(), r.m10(), r.m20());
        Vec3 y = new Vec3(r.m01(), r.m11(), r.m21());
        Vec3 z = new Vec3(r.m02(), r.m12(), r.m22());
        BodyShape s = p.def().shape();
        return s instanceof BodyShape.Box ? List.of(x, y, z) : s instanceof BodyShape.Cylinder ? List.of(z) : List.of();
    }

    /** Half the extent of a piece's projection on unit direction {@code l}. */
    private static double radius(Assembly.PlacedPiece p, Vec3 l) {
        Mat3 r = p.rotation();
        double lx = l.x() * r.m00() + l.y() * r.m10() + l.z() * r.m20();
        double ly = l.x() * r.m01() + l.y() * r.m11() + l.z() * r.m21();
        double lz = l.x() * r.m02() + l.y() * r.m12() + l.z() * r.m22();
        BodyShape s = p.def().shape();
        if (s instanceof BodyShape.Box b) {
            return Math.abs(lx) * b.hx() + Math.abs(ly) * b.hy() + Math.abs(lz) * b.hz();
        }
        if (s instanceof BodyShape.Cylinder c) {
            return c.radius() * Math.sqrt(Math.max(0, 1 - lz * lz)) + c.length() / 2 * Math.abs(lz);
        }
        return ((BodyShape.Sphere) s).radius();
    }

    /** The radius of a sphere round the piece. */
    private static double outer(BodyShape s) {
        if (s instanceof BodyShape.Box b) {
            return Math.max(b.hx(), Math.max(b.hy(), b.hz()));
        }
        if (s instanceof BodyShape.Cylinder c) {
            return Math.max(c.radius(), c.length() / 2);
        }
        return ((BodyShape.Sphere) s).radius();
    }
}
