package org.parpe.sim.internal;

import java.util.List;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DHingeJoint;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DMass;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeHelper;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.world.World;

/**
 * The ODE4j world of one assembled robot on a flat floor: one body per rigid cluster, one
 * geom per piece, one servo-driven hinge per segment. {@link #advance} runs a tick as equal
 * fixed sub-steps, so identical inputs give identical results. Not thread-safe: the engine
 * thread owns it.
 */
public final class PhysicsWorld implements AutoCloseable {
    private static final double GRAVITY = 9.81;

    static {
        OdeHelper.initODE2(0);
    }

    private final Assembly assembly;
    private final PhysicsParams params;
    private final DWorld world;
    /** The world's QuickStep without ODE4j's per-step task framework (allocates nothing; same results). */
    private final org.ode4j.ode.internal.processmem.SequentialQuickStep quickStep;
    private final DSpace space;
    private final DJointGroup contactGroup;
    private final DBody[] bodies;
    /** Mass of each body, kg ({@link DBody#getMass} makes a new object on every call). */
    private final double[] bodyMass;
    private final DGeom[] geoms;
    private final DHingeJoint[] hinges;
    private final double[] offset;
    private final double[] target;
    private final boolean[] limp;
    private final Contacts contacts;
    private final double totalMass;
    private final WorldBodies scenery;
    private double time;
    private long stepCount;
    private Docking docking;

    /** Builds the world for {@code assembly} on a flat floor. */
    public PhysicsWorld(Assembly assembly, PhysicsParams params) {
        this(assembly, params, null);
    }

    /** Builds the world for {@code assembly} in {@code scene} (null: a flat floor with {@code params}' friction). */
    public PhysicsWorld(Assembly assembly, PhysicsParams params, World scene) {
        this.assembly = assembly;
        this.params = params;
        world = OdeHelper.createWorld();
        world.setGravity(0, 0, -GRAVITY);
        world.setERP(0.2);
        world.setCFM(1e-5);
        world.setQuickStepNumIterations(params.iterations());
        world.setContactMaxCorrectingVel(0.2);
        world.setContactSurfaceLayer(0.0005);
        world.setAutoDisableFlag(false);
        quickStep = new org.ode4j.ode.internal.processmem.SequentialQuickStep(world,
                params.warmStart() > 0 ? new org.ode4j.ode.internal.WarmStart(params.warmStart()) : null);
        space = OdeHelper.createSapSpace(org.ode4j.ode.DSapSpace.AXES.XYZ);
        contactGroup = OdeHelper.createJointGroup();
        OdeHelper.createPlane(space, 0, 0, 1, 0)
                .setData(new WorldBodies.Surface(scene == null ? params.groundFriction() : scene.floorFriction()));
        bodies = new DBody[assembly.clusterCount()];
        geoms = new DGeom[assembly.pieces().size()];
        bodyMass = new double[bodies.length];
        double mass = 0;
        for (int c = 0; c < bodies.length; c++) {
            bodyMass[c] = createBody(c);
            mass += bodyMass[c];
        }
        totalMass = mass;
        int n = assembly.hinges().size();
        hinges = new DHingeJoint[n];
        offset = new double[n];
        target = new double[n];
        limp = new boolean[n];
        for (int h = 0; h < n; h++) {
            createHinge(h, assembly.hinges().get(h));
        }
        contacts = new Contacts(world, contactGroup, params, assembly);
        scenery = scene == null ? null : new WorldBodies(scene, world, space);
    }

    private double createBody(int cluster) {
        List<Assembly.PlacedPiece> pieces = assembly.pieces();
        DMass total = OdeHelper.createMass();
        total.setZero();
        for (Assembly.PlacedPiece p : pieces) {
            if (p.cluster() == cluster) {
                total.add(WorldBodies.pieceMass(p.def().shape(), p.def().mass(), p.rotation(), p.position()));
            }
        }
        DBody body = WorldBodies.bodyAtCentre(world, total);
        bodies[cluster] = body;
        for (int i = 0; i < pieces.size(); i++) {
            Assembly.PlacedPiece p = pieces.get(i);
            if (p.cluster() == cluster) {
                DGeom g = WorldBodies.geom(space, p.def().shape());
                g.setData(Integer.valueOf(i));
                g.setBody(body);
                g.setOffsetWorldPosition(p.position().x(), p.position().y(), p.position().z());
                g.setOffsetWorldRotation(WorldBodies.ode(p.rotation()));
                geoms[i] = g;
            }
        }
        return total.getMass();
    }

    private void createHinge(int h, Assembly.Hinge def) {
        DHingeJoint j = OdeHelper.createHingeJoint(world);
        // ODE measures the hinge angle as body 1 turning relative to body 2: the arm goes first so
        // that a positive angle turns the arm about +z of the base (PARSL.md §10 body frame).
        j.attach(bodies[assembly.pieces().get(def.arm()).cluster()], bodies[assembly.pieces().get(def.base()).cluster()]);
        j.setAnchor(def.anchor().x(), def.anchor().y(), def.anchor().z());
        j.setAxis(def.axis().x(), def.axis().y(), def.axis().z());
        offset[h] = def.angle();
        target[h] = def.angle();
        limp[h] = def.limp();
        j.setParamLoStop(-G1.SERVO.range() - def.angle());
        j.setParamHiStop(G1.SERVO.range() - def.angle());
        hinges[h] = j;
    }

    /** Sets the angle hinge {@code h} drives to, radians (clamped to the joint range). */
    public void setTarget(int h, double radians) {
        target[h] = Math.max(-G1.SERVO.range(), Math.min(G1.SERVO.range(), radians));
    }

    /** The angle hinge {@code h} drives to, radians. */
    public double target(int h) {
        return target[h];
    }

    /** Makes hinge {@code h} limp (back-drivable) or holding. */
    public void setLimp(int h, boolean value) {
        limp[h] = value;
    }

    public boolean limp(int h) {
        return limp[h];
    }

    /**
     * How deep, m, the robot is inside the world's scenery or movable objects now (0 when it is
     * clear of them or on the flat floor; the floor itself does not count): a robot placed at a
     * world's start that does not fit it. Not for the tick loop (it allocates).
     */
    public double sceneryOverlap() {
        if (scenery == null) {
            return 0;
        }
        double[] deepest = {0};
        org.ode4j.ode.DContactGeomBuffer found = new org.ode4j.ode.DContactGeomBuffer(8);
        DGeom.DNearCallback probe = (data, g1, g2) -> {
            boolean robot1 = g1.getData() instanceof Integer;
            boolean robot2 = g2.getData() instanceof Integer;
            if (robot1 == robot2 || (robot1 ? g2 : g1) instanceof org.ode4j.ode.DPlane) {
                return; // two parts of the robot, two things of the world, or the floor
            }
            int n = OdeHelper.collide(g1, g2, 8, found);
            for (int i = 0; i < n; i++) {
                deepest[0] = Math.max(deepest[0], found.get(i).depth);
            }
        };
        space.collide(null, probe);
        OdeHelper.spaceCollide2(space, scenery.fixedSpace(), null, probe);
        return deepest[0];
    }

    /** Advances by {@code dt} seconds in equal sub-steps; touch flags cover the whole interval. */
    public void advance(double dt) {
        int steps = Math.max(1, (int) Math.ceil(dt / params.maxSubstep() - 1e-9));
        double h = dt / steps;
        java.util.Arrays.fill(contacts.touch, 0);
        for (int s = 0; s < steps; s++) {
            driveServos();
            if (docking != null) {
                docking.pull();
            }
            contacts.clearKept();
            space.collide(null, contacts);
            if (scenery != null) {
                scenery.springs(h);
                OdeHelper.spaceCollide2(space, scenery.fixedSpace(), null, contacts);
            }
            // QuickStep reorders constraints with random numbers; seeding them from this world's
            // own step count keeps runs reproducible whatever else uses ODE.
            quickStep.seed(stepCount++);
            quickStep.step(h);
            contactGroup.empty();
        }
        time += dt;
    }

    /** Position loop of a hobby servo: speed proportional to the error, capped in speed and torque. */
    private void driveServos() {
        for (int h = 0; h < hinges.length; h++) {
            DHingeJoint j = hinges[h];
            if (limp[h]) {
                j.setParamVel(0);
                j.setParamFMax(G1.SERVO.limpTorque());
            } else {
                double err = target[h] - angle(h);
                double vel = Math.max(-G1.SERVO.speed(), Math.min(G1.SERVO.speed(), G1.SERVO.gain() * err));
                j.setParamVel(vel);
                j.setParamFMax(G1.SERVO.torque());
            }
        }
    }

    /** Simulated time, s. */
    public double time() {
        return time;
    }

    /** Measured angle of hinge {@code h}, radians. */
    public double angle(int h) {
        return hinges[h].getAngle() + offset[h];
    }

    /** Touch bits of hinge {@code h} over the last tick: 1 left (+y), 2 right (−y). */
    public int touch(int h) {
        return contacts.touch[h];
    }

    /** Number of hinges (segments), in ascending module ID. */
    public int hingeCount() {
        return hinges.length;
    }

    public Assembly assembly() {
        return assembly;
    }

    public int pieceCount() {
        return geoms.length;
    }

    /** World position of piece {@code i}; the returned view changes as the world moves. */
    public DVector3C piecePosition(int i) {
        return geoms[i].getPosition();
    }

    /** World rotation of piece {@code i}; the returned view changes as the world moves. */
    public DMatrix3C pieceRotation(int i) {
        return geoms[i].getRotation();
    }

    /** Writes the centre of mass into {@code out[0..2]}. */
    public void centerOfMass(double[] out) {
        double x = 0;
        double y = 0;
        double z = 0;
        for (int c = 0; c < bodies.length; c++) {
            double m = bodyMass[c];
            DVector3C p = bodies[c].getPosition();
            x += m * p.get0();
            y += m * p.get1();
            z += m * p.get2();
        }
        out[0] = x / totalMass;
        out[1] = y / totalMass;
        out[2] = z / totalMass;
    }

    /** Total mass, kg. */
    public double totalMass() {
        return totalMass;
    }

    /** Number of bodies (rigid clusters). */
    public int bodyCount() {
        return bodies.length;
    }

    /** The latches of the robot's plates (PARSL.md §14), made on first use. */
    public Docking docking() {
        if (docking == null) {
            docking = new Docking(this);
        }
        return docking;
    }

    /** The ODE world, for joints made during the run ({@link Docking}). */
    DWorld odeWorld() {
        return world;
    }

    /** The body of the rigid cluster that piece {@code i} belongs to. */
    DBody bodyOfPiece(int i) {
        return bodies[assembly.pieces().get(i).cluster()];
    }

    /** Contact points of the last sub-step (see {@link Contacts}). */
    Contacts contacts() {
        return contacts;
    }

    /** Kinetic plus potential energy of the robot, J (for tests). */
    public double energy() {
        double e = 0;
        for (DBody b : bodies) {
            double m = b.getMass().getMass();
            DVector3C v = b.getLinearVel();
            DVector3C w = b.getAngularVel();
            DMatrix3C r = b.getRotation();
            DMatrix3C inertia = b.getMass().getI();
            e += 0.5 * m * (v.get0() * v.get0() + v.get1() * v.get1() + v.get2() * v.get2());
            e += 0.5 * rotationalEnergyTwice(r, inertia, w);
            e += m * GRAVITY * b.getPosition().get2();
        }
        return e;
    }

    /** {@code ωᵀ R I Rᵀ ω} with ω in world coordinates. */
    private static double rotationalEnergyTwice(DMatrix3C r, DMatrix3C inertia, DVector3C w) {
        double[] local = new double[3];
        for (int i = 0; i < 3; i++) {
            local[i] = r.get(0, i) * w.get0() + r.get(1, i) * w.get1() + r.get(2, i) * w.get2();
        }
        double s = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                s += local[i] * inertia.get(i, j) * local[j];
            }
        }
        return s;
    }

    /** Whether any body's position or velocity is not finite. */
    public boolean hasNaN() {
        for (DBody b : bodies) {
            DVector3C p = b.getPosition();
            DVector3C v = b.getLinearVel();
            if (!Double.isFinite(p.get0() + p.get1() + p.get2() + v.get0() + v.get1() + v.get2())) {
                return true;
            }
        }
        return false;
    }

    /** World position of a piece as a record (setup and tests). */
    public Vec3 pieceCentre(int i) {
        DVector3C p = geoms[i].getPosition();
        return new Vec3(p.get0(), p.get1(), p.get2());
    }

    /** The world the robot is in, or null on the flat floor. */
    public World scene() {
        return scenery == null ? null : scenery.scene();
    }

    /** Number of movable objects of the world. */
    public int objectCount() {
        return scenery == null ? 0 : scenery.objectCount();
    }

    /** Writes the centre of mass of movable object {@code i} into {@code out[0..2]}. */
    public void objectCentre(int i, double[] out) {
        DVector3C p = scenery.objectPosition(i);
        out[0] = p.get0();
        out[1] = p.get1();
        out[2] = p.get2();
    }

    /** The geoms of movable object {@code i}, in the order of its pieces (snapshots). */
    DGeom[] objectGeoms(int i) {
        return scenery.objectGeoms(i);
    }

    /** How far lever {@code i} is turned from its rest stop, radians. */
    public double leverAngle(int i) {
        return scenery.leverAngle(i);
    }

    @Override
    public void close() {
        if (scenery != null) {
            scenery.destroy();
        }
        contactGroup.destroy();
        space.destroy();
        world.destroy();
    }
}
