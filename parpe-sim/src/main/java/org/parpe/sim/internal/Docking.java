package org.parpe.sim.internal;

import java.util.Arrays;
import java.util.List;
import org.ode4j.math.DMatrix3;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DQuaternion;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DFixedJoint;
import org.ode4j.ode.OdeHelper;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;

/**
 * Latching connection plates during a run (PARSL.md §14; the rules are in docs/simulator.md,
 * "Docking"). An armed plate draws in a free plate of another part when their centres are
 * within {@link #DRAW_DISTANCE}, their faces opposite within {@link #DRAW_ANGLE} and their
 * "up" directions within {@link #DRAW_ANGLE} of a 90° step: a damped spring between the plate
 * centres and a damped torque that squares the plates, both capped, act on the two bodies at
 * every physics step, as a latch's funnel and pins pull a plate home. Once the plates are within
 * {@link #LOCK_DISTANCE} and {@link #LOCK_ANGLE} the latch closes: an ODE fixed joint holds the
 * two bodies with the plates exactly aligned (the pins pull the plates home; the joint's error
 * correction takes up the last millimetre and degrees within a few steps) until a release
 * destroys it, and the two latched bodies no longer
 * collide with each other, as if the configuration bolted them. A plate reads
 * {@link #FREE}, {@link #IN_REACH} (a plate it could join is within {@link #REACH_DISTANCE} and
 * faces it within {@link #REACH_ANGLE}) or {@link #LATCHED}.
 *
 * <p>Only the plates of the configuration that no connection uses take part. Each check sorts
 * those plates' centres by x (an insertion sort, nearly sorted from the last tick) and looks only
 * at plates within the distance along x, so an armed plate's search does not scan every plate
 * pair; nothing is allocated per tick except the joint of a new latch.
 */
public final class Docking {
    /** A free plate with nothing it could join within reach. */
    public static final int FREE = 0;
    /** A plate it could join is within reach, but it is not latched. */
    public static final int IN_REACH = 1;
    /** Latched, or joined by the configuration. */
    public static final int LATCHED = 2;
    /** An armed plate draws a plate it can join from this distance between centres, m. */
    public static final double DRAW_DISTANCE = 0.03;
    /** ... and this misalignment of faces and of "up" directions (from a 90° step), rad. */
    public static final double DRAW_ANGLE = Math.toRadians(20);
    /** The pins are home, and the latch closes, within this distance between centres, m. */
    public static final double LOCK_DISTANCE = 0.002;
    /** ... and this misalignment, rad. */
    public static final double LOCK_ANGLE = Math.toRadians(3);
    /** Largest distance between centres at which a plate counts as within reach, m. */
    public static final double REACH_DISTANCE = 0.04;
    /** Largest angle between one face and the reverse of the other at which a plate counts as within reach, rad. */
    public static final double REACH_ANGLE = Math.toRadians(30);
    /** The draw: a spring of this stiffness between the centres, N/m, ... */
    private static final double PULL_STIFFNESS = 400;
    /** ... damped, N·s/m, ... */
    private static final double PULL_DAMPING = 4;
    /** ... at most this force, N (a G1 servo's 0.4 N·m at 13 cm). */
    private static final double PULL_MAX = 3;
    /** The draw turns the plates square with this stiffness, N·m/rad, ... */
    private static final double TURN_STIFFNESS = 0.15;
    /** ... damped, N·m·s/rad, ... */
    private static final double TURN_DAMPING = 0.002;
    /** ... at most this torque, N·m. */
    private static final double TURN_MAX = 0.05;

    private final PhysicsWorld world;
    private final Assembly.PlateSite[] sites;
    /** Per site: whether the configuration joins it. */
    private final boolean[] fixed;
    private final boolean[] armed;
    /** Per site: the site it is latched to, or −1. */
    private final int[] partner;
    /** Per armed site: the plate it draws in, or −1. */
    private final int[] drawing;
    private final org.ode4j.math.DVector3 va = new org.ode4j.math.DVector3();
    private final org.ode4j.math.DVector3 vb = new org.ode4j.math.DVector3();
    private final DFixedJoint[] joint;
    /** Per site: its world centre, normal and up of the last update. */
    private final double[] c;
    private final double[] n;
    private final double[] u;
    /** The free sites ordered by the x of their centres. */
    private final int[] byX;
    private final int[] state;
    private final int[] cluster;
    private int armedCount;

    /** Docking for the plates of {@code world}'s robot. */
    public Docking(PhysicsWorld world) {
        this.world = world;
        List<Assembly.PlateSite> list = world.assembly().plates();
        sites = list.toArray(new Assembly.PlateSite[0]);
        int count = sites.length;
        fixed = new boolean[count];
        armed = new boolean[count];
        partner = new int[count];
        drawing = new int[count];
        joint = new DFixedJoint[count];
        c = new double[3 * count];
        n = new double[3 * count];
        u = new double[3 * count];
        state = new int[count];
        cluster = new int[count];
        Arrays.fill(partner, -1);
        Arrays.fill(drawing, -1);
        int free = 0;
        for (int i = 0; i < count; i++) {
            fixed[i] = sites[i].connected();
            cluster[i] = world.assembly().pieces().get(sites[i].piece()).cluster();
            free += fixed[i] ? 0 : 1;
        }
        byX = new int[free];
        int k = 0;
        for (int i = 0; i < count; i++) {
            if (!fixed[i]) {
                byX[k++] = i;
            }
        }
    }

    /** The site of plate {@code plate} (0 or 1) of the segment with module ID {@code id}, or −1. */
    public int site(int id, int plate) {
        for (int i = 0; i < sites.length; i++) {
            if (sites[i].moduleId() == id && sites[i].plate() == plate) {
                return i;
            }
        }
        return -1;
    }

    /** Arms site {@code s}: it latches when a plate it can join is within capture (nothing for a joined plate). */
    public void arm(int s) {
        if (!fixed[s] && !armed[s]) {
            armed[s] = true;
            armedCount++;
        }
    }

    /** Disarms site {@code s} and releases its latch at once. */
    public void release(int s) {
        if (armed[s]) {
            armed[s] = false;
            armedCount--;
        }
        drawing[s] = -1;
        int p = partner[s];
        if (p >= 0) {
            joint[s].destroy();
            world.contacts().unlatch(cluster[s], cluster[p]);
            joint[s] = null;
            joint[p] = null;
            partner[s] = -1;
            partner[p] = -1;
        }
    }

    /** Whether site {@code s} is latched to another plate during the run. */
    public boolean latched(int s) {
        return partner[s] >= 0;
    }

    /** The reading of site {@code s} ({@link #FREE}, {@link #IN_REACH}, {@link #LATCHED}) as of the last {@link #update}. */
    public int reading(int s) {
        return fixed[s] || partner[s] >= 0 ? LATCHED : state[s];
    }

    /**
     * After a tick of physics: closes the latch of every armed plate whose pins are home, picks
     * the plate each other armed plate draws in, and, when {@code readings} is set, works out
     * which free plates have one within reach. Returns whether it looked at the plates at all.
     */
    public boolean update(boolean readings) {
        if (armedCount == 0 && !readings) {
            return false;
        }
        place();
        for (int k = 0; k < byX.length; k++) {
            int s = byX[k];
            drawing[s] = -1;
            if (partner[s] >= 0) {
                continue;
            }
            int best = armed[s] ? nearest(k, DRAW_DISTANCE, DRAW_ANGLE) : -1;
            if (best >= 0 && home(s, best)) {
                latch(s, best);
                continue;
            }
            drawing[s] = best;
            if (readings) {
                state[s] = best >= 0 || nearest(k, REACH_DISTANCE, REACH_ANGLE) >= 0 ? IN_REACH : FREE;
            }
        }
        if (armedCount > 0) {
            // a plate drawn by two armed plates is drawn by the first only (the order is by x, deterministic)
            for (int k = 0; k < byX.length; k++) {
                int s = byX[k];
                int o = drawing[s];
                if (o >= 0 && drawing[o] >= 0 && drawing[o] != s) {
                    drawing[o] = -1;
                }
            }
        }
        return true;
    }

    /** Whether the pins of {@code s} and {@code o} are home: centres and orientation within the lock tolerance. */
    private boolean home(int s, int o) {
        return dist2(s, o) <= LOCK_DISTANCE * LOCK_DISTANCE && -dot(n, s, o) >= Math.cos(LOCK_ANGLE)
                && Math.abs(squareness(s, o)) <= LOCK_ANGLE;
    }

    /**
     * At every physics step: each armed plate pulls the plate it draws in towards its centre and
     * turns it square, with equal and opposite forces and torques on the two bodies.
     */
    void pull() {
        if (armedCount == 0) {
            return;
        }
        for (int s : byX) {
            int o = drawing[s];
            if (o < 0 || partner[s] >= 0 || drawing[o] == s && o < s) {
                continue; // two armed plates that draw each other pull once
            }
            placeOne(s);
            placeOne(o);
            DBody a = world.bodyOfPiece(sites[s].piece());
            DBody b = world.bodyOfPiece(sites[o].piece());
            a.getPointVel(c[3 * s], c[3 * s + 1], c[3 * s + 2], va);
            b.getPointVel(c[3 * o], c[3 * o + 1], c[3 * o + 2], vb);
            double fx = PULL_STIFFNESS * (c[3 * o] - c[3 * s]) - PULL_DAMPING * (va.get0() - vb.get0());
            double fy = PULL_STIFFNESS * (c[3 * o + 1] - c[3 * s + 1]) - PULL_DAMPING * (va.get1() - vb.get1());
            double fz = PULL_STIFFNESS * (c[3 * o + 2] - c[3 * s + 2]) - PULL_DAMPING * (va.get2() - vb.get2());
            double f = Math.sqrt(fx * fx + fy * fy + fz * fz);
            double k = f > PULL_MAX ? PULL_MAX / f : 1;
            a.addForceAtPos(k * fx, k * fy, k * fz, c[3 * s], c[3 * s + 1], c[3 * s + 2]);
            b.addForceAtPos(-k * fx, -k * fy, -k * fz, c[3 * o], c[3 * o + 1], c[3 * o + 2]);
            turn(s, o, a, b);
        }
    }

    /** The torque that turns plate {@code s}'s face against {@code o}'s and its "up" onto {@code o}'s nearest 90° step. */
    private void turn(int s, int o, DBody a, DBody b) {
        // rotation error of a: n_s onto −n_o, and u_s onto the square of u_o (about n_s)
        double ex = n[3 * s + 1] * -n[3 * o + 2] - n[3 * s + 2] * -n[3 * o + 1];
        double ey = n[3 * s + 2] * -n[3 * o] - n[3 * s] * -n[3 * o + 2];
        double ez = n[3 * s] * -n[3 * o + 1] - n[3 * s + 1] * -n[3 * o];
        double twist = -squareness(s, o);
        ex += twist * n[3 * s];
        ey += twist * n[3 * s + 1];
        ez += twist * n[3 * s + 2];
        DVector3C wa = a.getAngularVel();
        DVector3C wb = b.getAngularVel();
        double tx = TURN_STIFFNESS * ex - TURN_DAMPING * (wa.get0() - wb.get0());
        double ty = TURN_STIFFNESS * ey - TURN_DAMPING * (wa.get1() - wb.get1());
        double tz = TURN_STIFFNESS * ez - TURN_DAMPING * (wa.get2() - wb.get2());
        double t = Math.sqrt(tx * tx + ty * ty + tz * tz);
        double k = t > TURN_MAX ? TURN_MAX / t : 1;
        a.addTorque(k * tx, k * ty, k * tz);
        b.addTorque(-k * tx, -k * ty, -k * tz);
    }

    /** The world poses of the free plates, and {@link #byX} sorted again. */
    private void place() {
        for (int s : byX) {
            placeOne(s);
        }
        for (int i = 1; i < byX.length; i++) {
            int s = byX[i];
            double x = c[3 * s];
            int j = i - 1;
            while (j >= 0 && c[3 * byX[j]] > x) {
                byX[j + 1] = byX[j];
                j--;
            }
            byX[j + 1] = s;
        }
    }

    /** The world centre, normal and up of site {@code s}, now. */
    private void placeOne(int s) {
        Assembly.PlateSite site = sites[s];
        DVector3C p = world.piecePosition(site.piece());
        DMatrix3C r = world.pieceRotation(site.piece());
        rotate(r, site.centre(), c, 3 * s);
        c[3 * s] += p.get0();
        c[3 * s + 1] += p.get1();
        c[3 * s + 2] += p.get2();
        rotate(r, site.normal(), n, 3 * s);
        rotate(r, site.up(), u, 3 * s);
    }

    private static void rotate(DMatrix3C r, Vec3 v, double[] out, int at) {
        out[at] = r.get00() * v.x() + r.get01() * v.y() + r.get02() * v.z();
        out[at + 1] = r.get10() * v.x() + r.get11() * v.y() + r.get12() * v.z();
        out[at + 2] = r.get20() * v.x() + r.get21() * v.y() + r.get22() * v.z();
    }

    /**
     * The nearest plate that the plate at {@code byX[k]} can join within {@code distance}: of
     * another part and another body, not latched, facing it within {@code angle}, its "up" within
     * {@code angle} of a 90° step.
     */
    private int nearest(int k, double distance, double angle) {
        int s = byX[k];
        double cosFace = Math.cos(angle);
        double x = c[3 * s];
        int best = -1;
        double bestD = distance * distance;
        for (int dir = -1; dir <= 1; dir += 2) {
            for (int j = k + dir; j >= 0 && j < byX.length; j += dir) {
                int o = byX[j];
                if (Math.abs(c[3 * o] - x) > distance) {
                    break;
                }
                if (sites[o].part() == sites[s].part() || partner[o] >= 0 || cluster[o] == cluster[s]) {
                    continue;
                }
                double d = dist2(s, o);
                if (d > bestD || -dot(n, s, o) < cosFace || Math.abs(squareness(s, o)) > angle) {
                    continue;
                }
                best = o;
                bestD = d;
            }
        }
        return best;
    }

    private double dist2(int a, int b) {
        double dx = c[3 * a] - c[3 * b];
        double dy = c[3 * a + 1] - c[3 * b + 1];
        double dz = c[3 * a + 2] - c[3 * b + 2];
        return dx * dx + dy * dy + dz * dz;
    }

    private static double dot(double[] v, int a, int b) {
        return v[3 * a] * v[3 * b] + v[3 * a + 1] * v[3 * b + 1] + v[3 * a + 2] * v[3 * b + 2];
    }

    /** How far, in radians and about plate {@code a}'s normal, the "up" of {@code b} is from a 90° step of {@code a}'s. */
    private double squareness(int a, int b) {
        double cos = dot(u, a, b);
        // (up_a × up_b) · n_a: the sine of the turn about plate a's normal
        double sin = (u[3 * a + 1] * u[3 * b + 2] - u[3 * a + 2] * u[3 * b + 1]) * n[3 * a]
                + (u[3 * a + 2] * u[3 * b] - u[3 * a] * u[3 * b + 2]) * n[3 * a + 1]
                + (u[3 * a] * u[3 * b + 1] - u[3 * a + 1] * u[3 * b]) * n[3 * a + 2];
        double turn = Math.atan2(sin, cos);
        return turn - Math.PI / 2 * Math.rint(turn / (Math.PI / 2));
    }

    private void latch(int s, int o) {
        drawing[s] = -1;
        drawing[o] = -1;
        DBody a = world.bodyOfPiece(sites[s].piece());
        DBody b = world.bodyOfPiece(sites[o].piece());
        DFixedJoint j = OdeHelper.createFixedJoint(world.odeWorld());
        j.attach(a, b);
        // the latch's pins are home: the joint holds b where plate o sits exactly on plate s
        DVector3 position = new DVector3(b.getPosition());
        DQuaternion orientation = new DQuaternion(b.getQuaternion());
        alignOnto(s, o, b);
        j.setFixed();
        b.setPosition(position);
        b.setQuaternion(orientation);
        joint[s] = j;
        joint[o] = j;
        partner[s] = o;
        partner[o] = s;
        world.contacts().latch(cluster[s], cluster[o]);
    }

    /**
     * Moves body {@code b} so that plate {@code o} lies exactly on plate {@code s}: centres
     * together, faces opposite, "up" on the nearest 90° step of {@code s}'s.
     */
    private void alignOnto(int s, int o, DBody b) {
        Vec3 ns = vec(n, s);
        Vec3 us = vec(u, s);
        double cos = dot(u, s, o);
        double sin = Geo.dot(Geo.cross(us, vec(u, o)), ns);
        int steps = (int) Math.floorMod(Math.round(Math.atan2(sin, cos) / (Math.PI / 2)), 4L);
        Vec3 side = Geo.cross(ns, us);
        Vec3 up = switch (steps) {
            case 0 -> us;
            case 1 -> side;
            case 2 -> Geo.scale(us, -1);
            default -> Geo.scale(side, -1);
        };
        Vec3 face = Geo.scale(ns, -1);
        Mat3 target = Geo.columns(face, up, Geo.cross(face, up));
        Vec3 no = vec(n, o);
        Vec3 uo = vec(u, o);
        Mat3 turn = Geo.mul(target, Geo.transpose(Geo.columns(no, uo, Geo.cross(no, uo))));
        DVector3C p = b.getPosition();
        Vec3 moved = Geo.add(vec(c, s), Geo.mul(turn, Geo.sub(new Vec3(p.get0(), p.get1(), p.get2()), vec(c, o))));
        DMatrix3C r = b.getRotation();
        Mat3 rot = Geo.mul(turn, new Mat3(r.get00(), r.get01(), r.get02(), r.get10(), r.get11(), r.get12(),
                r.get20(), r.get21(), r.get22()));
        b.setPosition(moved.x(), moved.y(), moved.z());
        b.setRotation(new DMatrix3(rot.m00(), rot.m01(), rot.m02(), rot.m10(), rot.m11(), rot.m12(),
                rot.m20(), rot.m21(), rot.m22()));
    }

    private static Vec3 vec(double[] v, int site) {
        return new Vec3(v[3 * site], v[3 * site + 1], v[3 * site + 2]);
    }
}
