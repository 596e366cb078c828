package org.parpe.sim.internal;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.config.Connection;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.RobotConfig;

/**
 * A configuration put together: every piece placed in the world at the initial pose, pieces
 * that are bolted together grouped into rigid clusters (one physics body each), and one hinge
 * per segment between its two clusters. Built once per simulator; reports every problem it
 * finds to a diagnostic sink.
 */
public final class Assembly {
    /** Allowed gap between two plates that close a loop, m. */
    private static final double LOOP_GAP = 0.003;
    /** Allowed misalignment of two plates that close a loop, rad. */
    private static final double LOOP_TWIST = Math.toRadians(3);

    /**
     * One rigid piece placed in the world.
     *
     * @param part     the part it belongs to
     * @param def      its geometry
     * @param position centre, world
     * @param rotation orientation, world
     * @param cluster  the rigid cluster (physics body) it belongs to
     */
    public record PlacedPiece(PartSpec part, PartGeometry.Piece def, Vec3 position, Mat3 rotation, int cluster) {
    }

    /**
     * One segment's hinge.
     *
     * @param moduleId    logical ID
     * @param base        index of the servo-half piece
     * @param arm         index of the turning-half piece
     * @param anchor      a point on the axis, world
     * @param axis        unit axis (the segment's z), world
     * @param angle       initial joint angle, radians
     * @param limp        whether the servo starts limp
     */
    public record Hinge(int moduleId, int base, int arm, Vec3 anchor, Vec3 axis, double angle, boolean limp) {
    }

    /**
     * One connection plate of the robot, for docking (PARSL.md §14): where it sits on its piece
     * and whether the configuration already joins it to another part.
     *
     * @param part      index of the part in the configuration
     * @param plate     the plate's number on its part (a segment's 0 and 1 are PARSL's plates)
     * @param piece     index of the piece that carries it
     * @param moduleId  the segment's module ID, or −1 for a passive part
     * @param centre    plate centre relative to the piece's centre, in the piece's frame
     * @param normal    outward unit normal, piece frame
     * @param up        unit "up" direction in the plate, piece frame
     * @param connected whether a connection of the configuration uses it
     */
    public record PlateSite(int part, int plate, int piece, int moduleId, Vec3 centre, Vec3 normal, Vec3 up,
                            boolean connected) {
    }

    /**
     * What a rolling robot (a wheel or a closed loop) is judged by for falling: one of its pieces
     * and the direction of its axle in that piece's own frame.
     *
     * @param piece the piece: the first hub, else the root segment's (or the first segment's) servo half
     * @param local the axle in the piece's frame (unit): the hub's disc axis, or the hinge axis
     */
    public record Axle(int piece, Vec3 local) {
    }

    /** How many assemblies {@link #build} has made in this class loader: a run should make one. */
    static final AtomicInteger BUILT = new AtomicInteger();

    private final List<PlacedPiece> pieces;
    private final List<Hinge> hinges;
    private final List<PlateSite> plates;
    private final int clusterCount;
    private final int rootPiece;
    private final Axle axle;

    private Assembly(List<PlacedPiece> pieces, List<Hinge> hinges, List<PlateSite> plates, int clusterCount,
                     int rootPiece, Axle axle) {
        this.pieces = List.copyOf(pieces);
        this.hinges = List.copyOf(hinges);
        this.plates = List.copyOf(plates);
        this.clusterCount = clusterCount;
        this.rootPiece = rootPiece;
        this.axle = axle;
    }

    /** Every connection plate, part by part in configuration order, each part's plates in order. */
    public List<PlateSite> plates() {
        return plates;
    }

    /** Pieces in configuration order (part by part, each part's pieces in order). */
    public List<PlacedPiece> pieces() {
        return pieces;
    }

    /** Hinges in ascending module ID. */
    public List<Hinge> hinges() {
        return hinges;
    }

    public int clusterCount() {
        return clusterCount;
    }

    /** The first piece of the root part. */
    public int rootPiece() {
        return rootPiece;
    }

    /** The axle of a rolling robot (one with a hub, or whose connections close a loop), or null. */
    public Axle axle() {
        return axle;
    }

    /** Assembles {@code config}; returns {@code null} after reporting errors to {@code diags}. */
    public static Assembly build(RobotConfig config, DiagnosticSink diags) {
        BUILT.incrementAndGet();
        ConfigCheck check = new ConfigCheck(config, diags);
        if (!check.run()) {
            return null;
        }
        Placement placement = new Placement(config, check.geometries(), diags);
        if (!placement.run()) {
            return null;
        }
        Assembly a = assemble(config, check.geometries(), placement, diags);
        return a == null || !Overlaps.check(a.pieces, a.hinges, diags) ? null : a;
    }

    private static Assembly assemble(RobotConfig config, List<PartGeometry> geos, Placement placement,
                                     DiagnosticSink diags) {
        List<PartSpec> parts = config.parts();
        int[] first = new int[parts.size()];
        int n = 0;
        for (int i = 0; i < parts.size(); i++) {
            first[i] = n;
            n += geos.get(i).pieces().size();
        }
        UnionFind uf = new UnionFind(n);
        Map<String, Integer> index = new HashMap<>();
        for (int i = 0; i < parts.size(); i++) {
            index.put(parts.get(i).name(), i);
        }
        for (Connection c : config.connections()) {
            int a = index.get(c.from());
            int b = index.get(c.to());
            uf.union(first[a] + geos.get(a).plates().get(c.fromPlate()).piece(),
                    first[b] + geos.get(b).plates().get(c.toPlate()).piece());
        }
        int[] cluster = uf.labels();
        boolean ok = true;
        for (int i = 0; i < parts.size(); i++) {
            if (parts.get(i).isSegment() && cluster[first[i]] == cluster[first[i] + 1]) {
                diags.error(parts.get(i).pos(), org.parpe.core.text.Msg.SEGMENT_CANNOT_TURN, parts.get(i).name());
                ok = false;
            }
        }
        if (!ok) {
            return null;
        }
        // Placement reached every part from a root, so one connection more than a tree per root has closes a loop.
        boolean loop = config.connections().size() > parts.size() - config.roots().size();
        return place(config, geos, placement, first, cluster, loop, plateSites(config, geos, first, index));
    }

    /** The plates of every part relative to their pieces (a piece turns with its plate, so joint angles do not matter). */
    private static List<PlateSite> plateSites(RobotConfig config, List<PartGeometry> geos, int[] first,
                                              Map<String, Integer> index) {
        java.util.Set<Long> used = new java.util.HashSet<>();
        for (Connection c : config.connections()) {
            used.add((long) index.get(c.from()) << 8 | c.fromPlate());
            used.add((long) index.get(c.to()) << 8 | c.toPlate());
        }
        List<PlateSite> out = new ArrayList<>();
        for (int i = 0; i < geos.size(); i++) {
            PartSpec part = config.parts().get(i);
            List<PartGeometry.Plate> plates = geos.get(i).plates();
            for (int k = 0; k < plates.size(); k++) {
                PartGeometry.Plate pl = plates.get(k);
                Vec3 pieceCentre = geos.get(i).pieces().get(pl.piece()).centre();
                out.add(new PlateSite(i, k, first[i] + pl.piece(), part.isSegment() ? part.moduleId() : -1,
                        Geo.sub(pl.centre(), pieceCentre), pl.normal(), pl.up(), used.contains((long) i << 8 | k)));
            }
        }
        return out;
    }

    private static Assembly place(RobotConfig config, List<PartGeometry> geos, Placement placement,
                                  int[] first, int[] cluster, boolean loop, List<PlateSite> plates) {
        List<PartSpec> parts = config.parts();
        List<PlacedPiece> placed = new ArrayList<>();
        List<Hinge> hinges = new ArrayList<>();
        for (int i = 0; i < parts.size(); i++) {
            PartSpec part = parts.get(i);
            Mat3 r = placement.rotation(i);
            Vec3 p = placement.position(i);
            double angle = Math.toRadians(part.angle());
            for (PartGeometry.Piece piece : geos.get(i).pieces()) {
                Mat3 pr = Geo.mul(r, PartGeometry.pieceRotation(piece, angle));
                Vec3 centre = Geo.add(p, Geo.mul(pr, piece.centre()));
                placed.add(new PlacedPiece(part, piece, centre, pr, cluster[placed.size()]));
            }
            if (part.isSegment()) {
                hinges.add(new Hinge(part.moduleId(), first[i], first[i] + 1, p,
                        Geo.mul(r, new Vec3(0, 0, 1)), angle, part.limp()));
            }
        }
        hinges.sort((a, b) -> Integer.compare(a.moduleId(), b.moduleId()));
        int clusters = Arrays.stream(cluster).max().orElse(-1) + 1;
        int root = placement.rootIndex();
        Assembly a = new Assembly(placed, hinges, plates, clusters, first[root],
                axleOf(parts, placed, hinges, first, root, loop));
        int[] chainOfPiece = new int[placed.size()];
        for (int i = 0; i < parts.size(); i++) {
            Arrays.fill(chainOfPiece, first[i], first[i] + geos.get(i).pieces().size(), placement.chain(i));
        }
        double[] lift = new double[config.roots().size()];
        for (int k = 0; k < lift.length; k++) {
            lift[k] = config.roots().get(k).height() - lowest(placed, chainOfPiece, k);
        }
        return a.lifted(chainOfPiece, lift);
    }

    /** This robot with each piece of robot {@code k} (of {@code chainOfPiece}) raised by {@code lift[k]}. */
    private Assembly lifted(int[] chainOfPiece, double[] lift) {
        List<PlacedPiece> out = new ArrayList<>();
        for (int i = 0; i < pieces.size(); i++) {
            PlacedPiece pp = pieces.get(i);
            out.add(new PlacedPiece(pp.part(), pp.def(), movedPoint(pp.position(), Mat3.IDENTITY, Vec3.ZERO,
                    new Vec3(0, 0, lift[chainOfPiece[i]])), Geo.mul(Mat3.IDENTITY, pp.rotation()), pp.cluster()));
        }
        List<Hinge> outHinges = new ArrayList<>();
        for (Hinge h : hinges) {
            outHinges.add(new Hinge(h.moduleId(), h.base(), h.arm(), movedPoint(h.anchor(), Mat3.IDENTITY, Vec3.ZERO,
                    new Vec3(0, 0, lift[chainOfPiece[h.base()]])), Geo.mul(Mat3.IDENTITY, h.axis()), h.angle(), h.limp()));
        }
        return new Assembly(out, outHinges, plates, clusterCount, rootPiece, axle);
    }

    /**
     * This robot turned by {@code turn} about {@code pivot}, then shifted by {@code shift}
     * (the same parts, clusters and joint angles).
     */
    private Assembly moved(Mat3 turn, Vec3 pivot, Vec3 shift) {
        List<PlacedPiece> out = new ArrayList<>();
        for (PlacedPiece pp : pieces) {
            out.add(new PlacedPiece(pp.part(), pp.def(), movedPoint(pp.position(), turn, pivot, shift),
                    Geo.mul(turn, pp.rotation()), pp.cluster()));
        }
        List<Hinge> outHinges = new ArrayList<>();
        for (Hinge h : hinges) {
            outHinges.add(new Hinge(h.moduleId(), h.base(), h.arm(), movedPoint(h.anchor(), turn, pivot, shift),
                    Geo.mul(turn, h.axis()), h.angle(), h.limp()));
        }
        return new Assembly(out, outHinges, plates, clusterCount, rootPiece, axle);
    }

    /** The axle a rolling robot is judged by ({@link Axle}), or null for a robot that does not roll. */
    private static Axle axleOf(List<PartSpec> parts, List<PlacedPiece> placed, List<Hinge> hinges, int[] first,
                               int root, boolean loop) {
        for (int i = 0; i < parts.size(); i++) {
            if (parts.get(i).type() == org.parpe.sim.config.PartType.HUB) {
                return new Axle(first[i], new Vec3(0, 0, 1));
            }
        }
        if (!loop || hinges.isEmpty()) {
            return null;
        }
        Hinge h = hinges.get(0);
        for (Hinge c : hinges) {
            if (c.base() == first[root]) {
                h = c;
            }
        }
        return new Axle(h.base(), Geo.mul(Geo.transpose(placed.get(h.base()).rotation()), h.axis()));
    }

    private static Vec3 movedPoint(Vec3 p, Mat3 turn, Vec3 pivot, Vec3 shift) {
        return Geo.add(Geo.add(pivot, Geo.mul(turn, Geo.sub(p, pivot))), shift);
    }

    /**
     * This robot placed at a world's start: turned about its root piece by {@code pitchDeg}
     * (nose up, about its own y) and then {@code yawDeg} (about the vertical), the root piece
     * moved to ({@code x}, {@code y}), and the whole lowered or raised so that its lowest point
     * rests {@code z} above the floor (plus the usual clearance).
     */
    public Assembly startingAt(double x, double y, double z, double yawDeg, double pitchDeg) {
        Mat3 turn = Geo.rollPitchYaw(0, -pitchDeg, yawDeg);
        Vec3 root = pieces.get(rootPiece).position();
        Assembly turned = moved(turn, root, new Vec3(x - root.x(), y - root.y(), 0));
        return turned.moved(Mat3.IDENTITY, Vec3.ZERO,
                new Vec3(0, 0, z + org.parpe.sim.config.RootPose.RESTING - lowest(turned.pieces)));
    }

    /** The lowest z of any piece. */
    private static double lowest(List<PlacedPiece> placed) {
        return lowest(placed, new int[placed.size()], 0);
    }

    /** The lowest z of any piece of robot {@code k}. */
    private static double lowest(List<PlacedPiece> placed, int[] chainOfPiece, int k) {
        double min = Double.POSITIVE_INFINITY;
        for (int i = 0; i < placed.size(); i++) {
            PlacedPiece pp = placed.get(i);
            if (chainOfPiece[i] == k) {
                min = Math.min(min, pp.position().z() - halfHeight(pp.def().shape(), pp.rotation()));
            }
        }
        return min;
    }

    /** Half the vertical extent of a shape with the given orientation. */
    public static double halfHeight(BodyShape shape, Mat3 r) {
        if (shape instanceof BodyShape.Box b) {
            return Math.abs(r.m20()) * b.hx() + Math.abs(r.m21()) * b.hy() + Math.abs(r.m22()) * b.hz();
        }
        if (shape instanceof BodyShape.Cylinder c) {
            double az = Math.abs(r.m22());
            return az * c.length() / 2 + c.radius() * Math.sqrt(Math.max(0, 1 - az * az));
        }
        return ((BodyShape.Sphere) shape).radius();
    }

    /** Disjoint sets over piece indices, labelled in order of first appearance. */
    private static final class UnionFind {
        private final int[] parent;

        UnionFind(int n) {
            parent = new int[n];
            for (int i = 0; i < n; i++) {
                parent[i] = i;
            }
        }

        int find(int i) {
            while (parent[i] != i) {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            return i;
        }

        void union(int a, int b) {
            int ra = find(a);
            int rb = find(b);
            if (ra != rb) {
                parent[Math.max(ra, rb)] = Math.min(ra, rb);
            }
        }

        int[] labels() {
            int[] label = new int[parent.length];
            int[] byRoot = new int[parent.length];
            Arrays.fill(byRoot, -1);
            int next = 0;
            for (int i = 0; i < parent.length; i++) {
                int r = find(i);
                if (byRoot[r] < 0) {
                    byRoot[r] = next++;
                }
                label[i] = byRoot[r];
            }
            return label;
        }
    }

    /** Breadth-first order of parts from the root; used by {@link Placement}. */
    static Deque<Integer> queueOf(int root) {
        Deque<Integer> q = new ArrayDeque<>();
        q.add(root);
        return q;
    }

    /** How far apart, m, the plates of a connection that closes a loop may be at the initial pose. */
    public static double loopGap() {
        return LOOP_GAP;
    }

    /** How far, rad, the plates of a connection that closes a loop may be turned against each other at the initial pose. */
    public static double loopTwist() {
        return LOOP_TWIST;
    }
}
