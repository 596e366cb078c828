package org.parpe.sim.internal;

import org.ode4j.ode.DBody;
import org.ode4j.ode.DContact;
import org.ode4j.ode.DContactBuffer;
import org.ode4j.ode.DContactGeom;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DPlane;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeConstants;
import org.ode4j.ode.OdeHelper;

/**
 * The near-phase collision callback: makes contact joints between pieces and with the ground,
 * skips pairs of bodies that share a hinge, records the touch side of every segment, and keeps
 * the contact points of the current sub-step for snapshots. Reuses its buffers.
 */
final class Contacts implements DGeom.DNearCallback {
    /** Contact points computed per pair of geoms. */
    private static final int PER_PAIR = 8;
    /** Contact points used per pair of geoms (the deepest ODE reports first). */
    private final int used;
    /** Contact points kept for a snapshot. */
    static final int KEPT = 512;

    private final DWorld world;
    private final DJointGroup group;
    private final PhysicsParams params;
    private final DContactBuffer buffer = new DContactBuffer(PER_PAIR);
    /** The buffer's contact geoms ({@link DContactBuffer#getGeomBuffer} makes a new view on every call). */
    private final org.ode4j.ode.DContactGeomBuffer geomBuffer = buffer.getGeomBuffer();
    /** Height above a floor, m, beyond which a bounding box does not meet it whatever the rounding. */
    private static final double CLEAR_OF_FLOOR = 1e-9;
    private final int[] clusterOf;
    private final int[] hingeOf;
    private final boolean[] sideSensing;
    private final double[] halfY;
    private final boolean[][] jointed;
    /** Per hinge: bit 0 left (+y) touched, bit 1 right (−y) touched, since the last clear. */
    final int[] touch;
    /** Kept contacts: x, y, z, nx, ny, nz, depth per contact. */
    final double[] kept = new double[KEPT * 7];
    /** Kept contacts: piece indices (second is −1 for the ground). */
    final int[] keptPieces = new int[KEPT * 2];
    int keptCount;

    Contacts(DWorld world, DJointGroup group, PhysicsParams params, Assembly assembly) {
        this.world = world;
        this.group = group;
        this.params = params;
        this.used = Math.min(PER_PAIR, params.contactsPerPair());
        int n = assembly.pieces().size();
        clusterOf = new int[n];
        hingeOf = new int[n];
        sideSensing = new boolean[n];
        halfY = new double[n];
        for (int i = 0; i < n; i++) {
            clusterOf[i] = assembly.pieces().get(i).cluster();
            hingeOf[i] = -1;
            if (assembly.pieces().get(i).def().shape() instanceof org.parpe.sim.geom.BodyShape.Box b) {
                halfY[i] = b.hy();
            }
        }
        jointed = new boolean[assembly.clusterCount()][assembly.clusterCount()];
        for (int h = 0; h < assembly.hinges().size(); h++) {
            Assembly.Hinge hinge = assembly.hinges().get(h);
            int a = clusterOf[hinge.base()];
            int b = clusterOf[hinge.arm()];
            jointed[a][b] = true;
            jointed[b][a] = true;
            hingeOf[hinge.base()] = h;
            hingeOf[hinge.arm()] = h;
            sideSensing[hinge.base()] = true;
            sideSensing[hinge.arm()] = true;
        }
        touch = new int[assembly.hinges().size()];
    }

    /** Pairs of clusters latched together during the run (PARSL.md §14): they do not collide, as if bolted. */
    private long[] latched = new long[0];
    private int latchedCount;

    /** Clusters {@code a} and {@code b} are latched together: they stop colliding. */
    void latch(int a, int b) {
        if (latchedCount == latched.length) {
            latched = java.util.Arrays.copyOf(latched, Math.max(4, 2 * latched.length));
        }
        latched[latchedCount++] = pair(a, b);
    }

    /** One latch between clusters {@code a} and {@code b} is released. */
    void unlatch(int a, int b) {
        long key = pair(a, b);
        for (int i = 0; i < latchedCount; i++) {
            if (latched[i] == key) {
                latched[i] = latched[--latchedCount];
                return;
            }
        }
    }

    private static long pair(int a, int b) {
        return (long) Math.min(a, b) << 32 | Math.max(a, b);
    }

    private boolean latchedTogether(int a, int b) {
        if (latchedCount == 0) {
            return false;
        }
        long key = pair(a, b);
        for (int i = 0; i < latchedCount; i++) {
            if (latched[i] == key) {
                return true;
            }
        }
        return false;
    }

    /** Forgets the kept contacts (at the start of every sub-step). */
    void clearKept() {
        keptCount = 0;
    }

    @Override
    public void call(Object data, DGeom g1, DGeom g2) {
        if (g1 instanceof DPlane f1 && aboveFloor(f1, g2) || g2 instanceof DPlane f2 && aboveFloor(f2, g1)) {
            return; // most parts, most of the time: the narrow phase would find no contact
        }
        int p1 = pieceOf(g1);
        int p2 = pieceOf(g2);
        if (p1 >= 0 && p2 >= 0 && (clusterOf[p1] == clusterOf[p2] || jointed[clusterOf[p1]][clusterOf[p2]]
                || latchedTogether(clusterOf[p1], clusterOf[p2]))) {
            return;
        }
        DBody b1 = g1.getBody();
        DBody b2 = g2.getBody();
        if (b1 == null && b2 == null || b1 == b2) {
            return; // two fixed things (the floor and a wall), or two pieces of one object
        }
        int n = Math.min(used, OdeHelper.collide(g1, g2, PER_PAIR, geomBuffer));
        double mu = friction(p1, g1, p2, g2);
        for (int i = 0; i < n; i++) {
            DContact c = buffer.get(i);
            c.surface.mode = OdeConstants.dContactApprox1 | OdeConstants.dContactSoftERP | OdeConstants.dContactSoftCFM;
            c.surface.mu = mu;
            c.surface.soft_erp = params.softErp();
            c.surface.soft_cfm = params.softCfm();
            OdeHelper.createContactJoint(world, group, c).attach(b1, b2);
            DContactGeom cg = c.geom;
            sense(p1, g1, cg.pos);
            sense(p2, g2, cg.pos);
            if (p1 >= 0 || p2 >= 0) {
                keep(cg, p1, p2);
            }
        }
    }

    /**
     * Whether {@code g}'s bounding box is above the horizontal plane {@code floor} by more than
     * {@link #CLEAR_OF_FLOOR}: then ODE's box-, cylinder- and sphere-plane tests, which compute
     * the lowest point of the shape in the same way, find no contact either (the margin is
     * far above their rounding errors, so the same pairs make contacts as without this test).
     */
    private boolean aboveFloor(DPlane floor, DGeom g) {
        DVector3C n = floor.getNormal();
        return n.get0() == 0 && n.get1() == 0 && n.get2() == 1 && g.getAABB().getMin2() > floor.getDepth() + CLEAR_OF_FLOOR;
    }

    /**
     * Friction of a contact: the robot's parts on each other {@code selfFriction}; a part on the
     * floor or the scenery that surface's own; two scenery objects the geometric mean of theirs.
     */
    private double friction(int p1, DGeom g1, int p2, DGeom g2) {
        if (p1 >= 0 && p2 >= 0) {
            return params.selfFriction();
        }
        if (p1 >= 0) {
            return surface(g2);
        }
        if (p2 >= 0) {
            return surface(g1);
        }
        return Math.sqrt(surface(g1) * surface(g2));
    }

    private double surface(DGeom g) {
        return g.getData() instanceof WorldBodies.Surface s ? s.friction() : params.groundFriction();
    }

    private static int pieceOf(DGeom g) {
        Object d = g.getData();
        return d instanceof Integer i ? i : -1;
    }

    /** Marks the touched side of a segment half: the contact point's local y against the half's width. */
    private void sense(int piece, DGeom g, DVector3C p) {
        if (piece < 0 || !sideSensing[piece]) {
            return;
        }
        DVector3C c = g.getPosition();
        DMatrix3C r = g.getRotation();
        double dx = p.get0() - c.get0();
        double dy = p.get1() - c.get1();
        double dz = p.get2() - c.get2();
        double localY = r.get01() * dx + r.get11() * dy + r.get21() * dz;
        if (localY > 0.5 * halfY[piece]) {
            touch[hingeOf[piece]] |= 1;
        } else if (localY < -0.5 * halfY[piece]) {
            touch[hingeOf[piece]] |= 2;
        }
    }

    private void keep(DContactGeom cg, int p1, int p2) {
        if (keptCount >= KEPT) {
            return;
        }
        int k = keptCount * 7;
        kept[k] = cg.pos.get0();
        kept[k + 1] = cg.pos.get1();
        kept[k + 2] = cg.pos.get2();
        kept[k + 3] = cg.normal.get0();
        kept[k + 4] = cg.normal.get1();
        kept[k + 5] = cg.normal.get2();
        kept[k + 6] = cg.depth;
        keptPieces[keptCount * 2] = p1 >= 0 ? p1 : p2;
        keptPieces[keptCount * 2 + 1] = p1 >= 0 ? p2 : -1;
        keptCount++;
    }
}
