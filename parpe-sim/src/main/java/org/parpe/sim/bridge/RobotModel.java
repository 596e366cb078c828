package org.parpe.sim.bridge;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.config.Connection;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.internal.Assembly;
import org.parpe.sim.internal.G1;
import org.parpe.sim.internal.PhysicsParams;

/**
 * A configuration as the other tools see it: one link per rigid piece (a segment's two halves
 * are two links), placed at the configuration's initial pose; one revolute joint per segment
 * (named {@code m<ID>}) and one fixed joint per plate connection. The links form a tree from the
 * root part's first piece; a connection that closes a loop is left out of the tree and kept as a
 * {@link #closures() closure} (every loop of a G1 robot has a bolted connection, so no servo is
 * ever a closure). Pieces that the simulator never lets collide (one rigid cluster, or two
 * clusters sharing a hinge) are listed as {@link #excluded() excluded pairs}.
 */
public final class RobotModel {
    /**
     * One rigid piece.
     *
     * @param name     unique name: the part's, with {@code _base}/{@code _arm} for segment halves
     * @param shape    its collision shape, centred on the link frame
     * @param mass     kg
     * @param position link frame origin (the piece centre), world, at the initial pose
     * @param rotation link frame orientation, world
     * @param part     the part it belongs to (for located messages)
     */
    public record Link(String name, BodyShape shape, double mass, Vec3 position, Mat3 rotation, PartSpec part) {
    }

    /**
     * A joint of the tree: the child link hangs from the parent link.
     *
     * @param name     {@code m<ID>} for a segment's servo, {@code PARENT__CHILD} for a fixed joint
     * @param parent   parent link index
     * @param child    child link index
     * @param moduleId the segment's module ID, or −1 for a fixed joint
     * @param anchor   a point of the axis, world (revolute joints)
     * @param axis     unit axis, world, oriented so that a positive joint value is a positive module angle
     * @param initial  the module's initial angle, radians (the joint value of the initial pose)
     */
    public record Joint(String name, int parent, int child, int moduleId, Vec3 anchor, Vec3 axis, double initial) {
        /** Whether it is a segment's servo. */
        public boolean revolute() {
            return moduleId >= 0;
        }
    }

    /**
     * A bolted connection that closes a loop, left out of the tree.
     *
     * @param name  {@code A__B}
     * @param a     one link index
     * @param b     the other
     * @param where the connection in the configuration file
     */
    public record Closure(String name, int a, int b, Connection where) {
    }

    private final String name;
    private final List<Link> links;
    private final List<Joint> joints;
    private final List<Closure> closures;
    private final List<int[]> excluded;
    private final Assembly.Axle axle;

    private RobotModel(String name, List<Link> links, List<Joint> joints, List<Closure> closures, List<int[]> excluded,
                       Assembly.Axle axle) {
        this.name = name;
        this.axle = axle;
        this.links = List.copyOf(links);
        this.joints = List.copyOf(joints);
        this.closures = List.copyOf(closures);
        this.excluded = List.copyOf(excluded);
    }

    /** The model of {@code config}, whose assembly is {@code a}. */
    public static RobotModel of(RobotConfig config, Assembly a) {
        List<Link> links = new ArrayList<>();
        for (Assembly.PlacedPiece p : a.pieces()) {
            String suffix = !p.part().isSegment() ? "" : p.def().turns() ? "_arm" : "_base";
            links.add(new Link(p.part().name() + suffix, p.def().shape(), p.def().mass(), p.position(), p.rotation(),
                    p.part()));
        }
        // edges: hinges first, then bolts, so that a loop is always cut at a bolt
        Map<String, Integer> firstPiece = new HashMap<>();
        for (int i = a.pieces().size() - 1; i >= 0; i--) {
            firstPiece.put(a.pieces().get(i).part().name(), i);
        }
        List<int[]> edges = new ArrayList<>();
        List<Object> what = new ArrayList<>();
        for (Assembly.Hinge h : a.hinges()) {
            edges.add(new int[] {h.base(), h.arm()});
            what.add(h);
        }
        for (Connection c : config.connections()) {
            edges.add(new int[] {pieceOf(a, firstPiece, c.from(), c.fromPlate()), pieceOf(a, firstPiece, c.to(), c.toPlate())});
            what.add(c);
        }
        int[] parent = new int[links.size()];
        Arrays.fill(parent, -1);
        int[] sets = new int[links.size()];
        for (int i = 0; i < sets.length; i++) {
            sets[i] = i;
        }
        List<List<Integer>> adjacent = new ArrayList<>();
        links.forEach(l -> adjacent.add(new ArrayList<>()));
        List<Closure> closures = new ArrayList<>();
        for (int e = 0; e < edges.size(); e++) {
            int x = find(sets, edges.get(e)[0]);
            int y = find(sets, edges.get(e)[1]);
            if (x == y) {
                Connection c = (Connection) what.get(e);
                closures.add(new Closure(fixedName(links, edges.get(e)[0], edges.get(e)[1]), edges.get(e)[0],
                        edges.get(e)[1], c));
                continue;
            }
            sets[Math.max(x, y)] = Math.min(x, y);
            adjacent.get(edges.get(e)[0]).add(e);
            adjacent.get(edges.get(e)[1]).add(e);
        }
        List<Joint> joints = orient(a.rootPiece(), links, edges, what, adjacent);
        return new RobotModel(config.name(), links, joints, closures, excludedPairs(a, joints), a.axle());
    }

    private static int pieceOf(Assembly a, Map<String, Integer> firstPiece, String part, int plate) {
        int first = firstPiece.get(part);
        for (Assembly.PlateSite s : a.plates()) {
            if (s.piece() >= first && a.pieces().get(s.piece()).part().name().equals(part) && s.plate() == plate) {
                return s.piece();
            }
        }
        throw new IllegalStateException("no plate " + part + "." + plate);
    }

    private static int find(int[] sets, int i) {
        while (sets[i] != i) {
            i = sets[i];
        }
        return i;
    }

    /** The tree's joints, parents before children, breadth first from {@code root}. */
    private static List<Joint> orient(int root, List<Link> links, List<int[]> edges, List<Object> what,
                                      List<List<Integer>> adjacent) {
        List<Joint> joints = new ArrayList<>();
        boolean[] seen = new boolean[links.size()];
        Deque<Integer> queue = new ArrayDeque<>();
        queue.add(root);
        seen[root] = true;
        while (!queue.isEmpty()) {
            int at = queue.poll();
            for (int e : adjacent.get(at)) {
                int[] ends = edges.get(e);
                int child = ends[0] == at ? ends[1] : ends[0];
                if (seen[child]) {
                    continue;
                }
                seen[child] = true;
                queue.add(child);
                if (what.get(e) instanceof Assembly.Hinge h) {
                    // the arm turns by +angle about the axis relative to the base; seen from the arm the base turns by −angle
                    Vec3 axis = child == h.arm() ? h.axis() : Geo.scale(h.axis(), -1);
                    joints.add(new Joint("m" + h.moduleId(), at, child, h.moduleId(), h.anchor(), axis, h.angle()));
                } else {
                    joints.add(new Joint(fixedName(links, at, child), at, child, -1, null, null, 0));
                }
            }
        }
        return joints;
    }

    private static String fixedName(List<Link> links, int a, int b) {
        return links.get(a).name() + "__" + links.get(b).name();
    }

    /** Pairs of links in one rigid cluster, or in two clusters that share a hinge, that are not parent and child. */
    private static List<int[]> excludedPairs(Assembly a, List<Joint> joints) {
        int clusters = a.clusterCount();
        boolean[][] together = new boolean[clusters][clusters];
        for (int c = 0; c < clusters; c++) {
            together[c][c] = true;
        }
        for (Assembly.Hinge h : a.hinges()) {
            int x = a.pieces().get(h.base()).cluster();
            int y = a.pieces().get(h.arm()).cluster();
            together[x][y] = true;
            together[y][x] = true;
        }
        java.util.Set<Long> parentChild = new java.util.HashSet<>();
        for (Joint j : joints) {
            parentChild.add((long) Math.min(j.parent(), j.child()) << 32 | Math.max(j.parent(), j.child()));
        }
        List<int[]> out = new ArrayList<>();
        int n = a.pieces().size();
        for (int i = 0; i < n; i++) {
            for (int k = i + 1; k < n; k++) {
                if (together[a.pieces().get(i).cluster()][a.pieces().get(k).cluster()]
                        && !parentChild.contains((long) i << 32 | k)) {
                    out.add(new int[] {i, k});
                }
            }
        }
        return out;
    }

    public String name() {
        return name;
    }

    /** Links, in configuration order; link 0 need not be the root. */
    public List<Link> links() {
        return links;
    }

    /** The tree's joints, each parent's joint before its children's. */
    public List<Joint> joints() {
        return joints;
    }

    public List<Closure> closures() {
        return closures;
    }

    public List<int[]> excluded() {
        return excluded;
    }

    /**
     * The axle a rolling robot (a wheel, a loop) is judged by for falling, as the simulator judges
     * it: a link (index) and a unit direction in its frame; null for a robot that does not roll.
     * Link {@code i} is piece {@code i} of the assembly, in the same frame.
     */
    public Assembly.Axle axle() {
        return axle;
    }

    /** The root link: the one no joint has as its child. */
    public int root() {
        boolean[] child = new boolean[links.size()];
        joints.forEach(j -> child[j.child()] = true);
        for (int i = 0; i < child.length; i++) {
            if (!child[i]) {
                return i;
            }
        }
        throw new IllegalStateException("no root");
    }

    /** The joint whose child is link {@code i}, or null for the root. */
    public Joint jointOf(int i) {
        for (Joint j : joints) {
            if (j.child() == i) {
                return j;
            }
        }
        return null;
    }

    /** The pose of link {@code child} in the frame of link {@code parent}: position. */
    public Vec3 relativePosition(int parent, int child) {
        Link p = links.get(parent);
        return Geo.mul(Geo.transpose(p.rotation()), Geo.sub(links.get(child).position(), p.position()));
    }

    /** The pose of link {@code child} in the frame of link {@code parent}: orientation. */
    public Mat3 relativeRotation(int parent, int child) {
        return Geo.mul(Geo.transpose(links.get(parent).rotation()), links.get(child).rotation());
    }

    /** A world point in the frame of link {@code i}. */
    public Vec3 local(int i, Vec3 world) {
        Link l = links.get(i);
        return Geo.mul(Geo.transpose(l.rotation()), Geo.sub(world, l.position()));
    }

    /** A world direction in the frame of link {@code i}. */
    public Vec3 localDirection(int i, Vec3 world) {
        return Geo.mul(Geo.transpose(links.get(i).rotation()), world);
    }

    /** Principal moments of inertia of link {@code i} about its centre, in its frame (x, y, z), kg·m². */
    public Vec3 inertia(int i) {
        Link l = links.get(i);
        double m = l.mass();
        if (l.shape() instanceof BodyShape.Box b) {
            double x = 2 * b.hx();
            double y = 2 * b.hy();
            double z = 2 * b.hz();
            return new Vec3(m * (y * y + z * z) / 12, m * (x * x + z * z) / 12, m * (x * x + y * y) / 12);
        }
        if (l.shape() instanceof BodyShape.Cylinder c) {
            double side = m * (3 * c.radius() * c.radius() + c.length() * c.length()) / 12;
            return new Vec3(side, side, m * c.radius() * c.radius() / 2);
        }
        double r = ((BodyShape.Sphere) l.shape()).radius();
        double s = 2 * m * r * r / 5;
        return new Vec3(s, s, s);
    }

    /** The servo's stall torque, N·m. */
    public static double torque() {
        return G1.SERVO.torque();
    }

    /** The servo's speed limit, rad/s. */
    public static double speed() {
        return G1.SERVO.speed();
    }

    /** The joint range each side of zero (absolute module angle), rad. */
    public static double range() {
        return G1.SERVO.range();
    }

    /** The servo position loop's gain, 1/s. */
    public static double gain() {
        return G1.SERVO.gain();
    }

    /** Friction of the robot's parts on the floor. */
    public static double groundFriction() {
        return PhysicsParams.defaults().groundFriction();
    }

    /** Friction of the robot's parts on each other. */
    public static double selfFriction() {
        return PhysicsParams.defaults().selfFriction();
    }

    /** The simulator's physics step, s. */
    public static double step() {
        return PhysicsParams.defaults().maxSubstep();
    }
}
