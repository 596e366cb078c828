package org.parpe.sim.internal;

import java.util.List;
import org.ode4j.math.DMatrix3;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DHingeJoint;
import org.ode4j.ode.DMass;
import org.ode4j.ode.DMassC;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeHelper;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.world.World;

/**
 * The ODE bodies and geoms of a {@link World}'s scenery: fixed solids as geoms without a body
 * (in their own space, so that the broad phase never pairs two of them), each movable object as
 * one body of its pieces, each lever's arm on a hinge fixed to the world with a torsion spring.
 * Every geom carries its {@link Surface} for the contact callback.
 */
final class WorldBodies {
    /** Damping of a lever's spring, N·m·s per radian (keeps it from ringing). */
    private static final double LEVER_DAMPING = 0.002;

    /** What a geom that is not part of the robot is made of. */
    record Surface(double friction) {
    }

    private final World scene;
    private final DSpace fixed;
    private final DBody[] bodies;
    private final DGeom[][] geoms;
    private final DHingeJoint[] hinges;
    private final double[] stiffness;
    /** Each lever's moment of inertia about its hinge, kg·m². */
    private final double[] inertia;

    WorldBodies(World scene, DWorld world, DSpace moving) {
        this.scene = scene;
        fixed = OdeHelper.createSapSpace(org.ode4j.ode.DSapSpace.AXES.XYZ);
        for (World.Solid s : scene.solids()) {
            DGeom g = geom(fixed, s.shape());
            g.setData(new Surface(s.friction()));
            g.setPosition(s.position().x(), s.position().y(), s.position().z());
            g.setRotation(ode(s.rotation()));
        }
        List<World.MovableObject> objects = scene.objects();
        bodies = new DBody[objects.size()];
        geoms = new DGeom[objects.size()][];
        for (int i = 0; i < objects.size(); i++) {
            createObject(i, objects.get(i), world, moving);
        }
        hinges = new DHingeJoint[scene.levers().size()];
        stiffness = new double[hinges.length];
        inertia = new double[hinges.length];
        for (int i = 0; i < hinges.length; i++) {
            World.Lever l = scene.levers().get(i);
            DHingeJoint j = OdeHelper.createHingeJoint(world);
            j.attach(bodies[l.object()], null);
            j.setAnchor(l.pivot().x(), l.pivot().y(), l.pivot().z());
            j.setAxis(l.axis().x(), l.axis().y(), l.axis().z());
            j.setParamLoStop(0);
            j.setParamHiStop(l.maxAngle());
            hinges[i] = j;
            stiffness[i] = l.stiffness();
            inertia[i] = inertia(bodies[l.object()], l);
        }
    }

    /**
     * The moment of inertia of a lever's arm about its hinge axis (the body is not yet turned, so
     * its frame is the world's): about its centre, plus its mass times the centre's distance
     * from the axis squared.
     */
    private static double inertia(DBody arm, World.Lever l) {
        DMassC m = arm.getMass();
        DMatrix3C i = m.getI();
        Vec3 a = l.axis();
        double[] v = {a.x(), a.y(), a.z()};
        double about = 0;
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                about += v[r] * i.get(r, c) * v[c];
            }
        }
        DVector3C p = arm.getPosition();
        Vec3 d = new Vec3(p.get0() - l.pivot().x(), p.get1() - l.pivot().y(), p.get2() - l.pivot().z());
        double along = Geo.dot(d, a) / Geo.dot(a, a);
        return about / Geo.dot(a, a) + m.getMass() * (Geo.dot(d, d) - along * along * Geo.dot(a, a));
    }

    private void createObject(int index, World.MovableObject o, DWorld world, DSpace moving) {
        double volume = 0;
        for (World.Piece p : o.pieces()) {
            volume += volume(p.shape());
        }
        DMass total = OdeHelper.createMass();
        total.setZero();
        for (World.Piece p : o.pieces()) {
            total.add(pieceMass(p.shape(), o.mass() * volume(p.shape()) / volume, Geo.mul(o.rotation(), p.rotation()),
                    Geo.add(o.position(), Geo.mul(o.rotation(), p.offset()))));
        }
        DBody body = bodyAtCentre(world, total);
        bodies[index] = body;
        geoms[index] = new DGeom[o.pieces().size()];
        for (int k = 0; k < o.pieces().size(); k++) {
            World.Piece p = o.pieces().get(k);
            DGeom g = geom(moving, p.shape());
            g.setData(new Surface(o.friction()));
            g.setBody(body);
            Vec3 at = Geo.add(o.position(), Geo.mul(o.rotation(), p.offset()));
            g.setOffsetWorldPosition(at.x(), at.y(), at.z());
            g.setOffsetWorldRotation(ode(Geo.mul(o.rotation(), p.rotation())));
            geoms[index][k] = g;
        }
    }

    /** The mass {@code mass} of a solid {@code shape} turned by {@code rotation} with its centre at {@code at}. */
    static DMass pieceMass(BodyShape shape, double mass, Mat3 rotation, Vec3 at) {
        DMass m = OdeHelper.createMass();
        if (shape instanceof BodyShape.Box b) {
            m.setBoxTotal(mass, 2 * b.hx(), 2 * b.hy(), 2 * b.hz());
        } else if (shape instanceof BodyShape.Cylinder c) {
            m.setCylinderTotal(mass, 3, c.radius(), c.length());
        } else {
            m.setSphereTotal(mass, ((BodyShape.Sphere) shape).radius());
        }
        m.rotate(ode(rotation));
        m.translate(at.x(), at.y(), at.z());
        return m;
    }

    /** A body of mass {@code total} (given about the world origin), placed at its centre of mass. */
    static DBody bodyAtCentre(DWorld world, DMass total) {
        DVector3C c = total.getC();
        double cx = c.get0();
        double cy = c.get1();
        double cz = c.get2();
        total.translate(-cx, -cy, -cz);
        DBody body = OdeHelper.createBody(world);
        body.setPosition(cx, cy, cz);
        body.setMass(total);
        return body;
    }

    private static double volume(BodyShape s) {
        if (s instanceof BodyShape.Box b) {
            return 8 * b.hx() * b.hy() * b.hz();
        }
        if (s instanceof BodyShape.Cylinder c) {
            return Math.PI * c.radius() * c.radius() * c.length();
        }
        double r = ((BodyShape.Sphere) s).radius();
        return 4.0 / 3 * Math.PI * r * r * r;
    }

    static DGeom geom(DSpace space, BodyShape shape) {
        if (shape instanceof BodyShape.Box b) {
            return OdeHelper.createBox(space, 2 * b.hx(), 2 * b.hy(), 2 * b.hz());
        }
        if (shape instanceof BodyShape.Cylinder c) {
            return OdeHelper.createCylinder(space, c.radius(), c.length());
        }
        return OdeHelper.createSphere(space, ((BodyShape.Sphere) shape).radius());
    }

    static DMatrix3 ode(Mat3 m) {
        return new DMatrix3(m.m00(), m.m01(), m.m02(), m.m10(), m.m11(), m.m12(), m.m20(), m.m21(), m.m22());
    }

    /** The space of the fixed solids (the moving one is the robot's). */
    DSpace fixedSpace() {
        return fixed;
    }

    /**
     * Applies each lever's return spring for the coming sub-step of {@code h} seconds. The torque
     * is explicit, so a very light arm (a 1 mm, 1 g lever) would gain energy each sub-step and
     * end in NaN: stiffness and damping are capped at half of what the arm's inertia can follow
     * in one sub-step (k·h²/I and c·h/I at most 1/2). Every lever of a usual size stays far below
     * the caps and moves as before.
     */
    void springs(double h) {
        for (int i = 0; i < hinges.length; i++) {
            double k = Math.min(stiffness[i], 0.5 * inertia[i] / (h * h));
            double c = Math.min(LEVER_DAMPING, 0.5 * inertia[i] / h);
            hinges[i].addTorque(-k * hinges[i].getAngle() - c * hinges[i].getAngleRate());
        }
    }

    World scene() {
        return scene;
    }

    int objectCount() {
        return bodies.length;
    }

    /** Centre of mass of object {@code i}; the view changes as the world moves. */
    DVector3C objectPosition(int i) {
        return bodies[i].getPosition();
    }

    DGeom[] objectGeoms(int i) {
        return geoms[i];
    }

    /** How far lever {@code i} is turned from its rest stop, radians. */
    double leverAngle(int i) {
        return hinges[i].getAngle();
    }

    void destroy() {
        fixed.destroy();
    }
}
