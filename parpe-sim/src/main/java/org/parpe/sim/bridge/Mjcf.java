package org.parpe.sim.bridge;

import java.util.ArrayList;
import java.util.List;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.internal.Docking;

/**
 * A robot as MuJoCo MJCF, in the subset that MuJoCo 2.2 and 3 both read: nested bodies at the
 * initial pose, the root body free; a hinge joint {@code m<ID>} per segment whose value is the
 * module's angle in radians ({@code ref} is the initial angle); a position servo {@code m<ID>} per
 * joint whose control is that angle, with the servo's torque as its force range; loops
 * closed by {@code weld} equality constraints; the simulator's contact exclusions; friction on
 * the floor and between parts, in Coulomb's (elliptic) cone; a 0.5 ms step (the servo's
 * stiffness needs it; MuJoCo's loop closures are soft constraints, and PARPE's 5 ms step lets a
 * 12-module loop open by 6 mm there).
 */
public final class Mjcf {
    /**
     * Position gain of the servos, N·m/rad. PARPE's servo is a velocity loop (ODE's joint motor,
     * a constraint: it holds the speed it is told, gain × error capped at the servo's speed, with
     * up to its torque); as an MJCF servo that is {@code kv·(gain·(ctrl − q) − q̇)}, stiffer the
     * larger kv. With kv = 0.2 N·m·s/rad (kp = 40 × 0.2 = 8) the joint angles follow PARPE's
     * within about 1° (RMS over a hello-snake run), and a stiffer servo brings the gaits no nearer
     * PARPE's (kv 1, stable at a 0.05 ms step: hello-snake 0.57 m instead of 0.61 m). A stiffer
     * one is not stable at 0.5 ms: while the force range clamps a servo, MuJoCo integrates its
     * force explicitly, and 0.4 N·m for one step moves the lightest joint (1.1e-5 kg·m² as MuJoCo
     * sees it) by 18 rad/s, far across the 0.4/kv rad/s in which the servo is not clamped, so it
     * chatters from bound to bound, the more the stiffer (measured: kv 0.5 diverges at 0.5 ms, kv 2
     * at 0.25 ms, kv 1 holds at 0.1 ms; docs/decisions.md, "PARPE's step and the MuJoCo cross-check").
     */
    static final double KP = 8;
    /** The custom numeric that tells a runner the servo's speed limit, rad/s. */
    public static final String SERVO_SPEED = "servo_speed";
    /** The site on a rolling robot's axle (see {@link RobotModel#axle()}), its z axis the axle. */
    public static final String AXLE = "axle";
    /** MuJoCo's step, s: stable with the servo's {@link #KP} and keeps a loop closed within 0.5 mm. */
    static final double STEP = 0.0005;

    private Mjcf() {
    }

    /**
     * The custom numeric that tells a runner when an armed pair latches: the distance between plate
     * centres, m, and the misalignment, rad, from which PARPE's latch draws a plate in
     * ({@link Docking#DRAW_DISTANCE}, {@link Docking#DRAW_ANGLE}). MuJoCo has no draw force; the
     * weld, a soft constraint, pulls the plates home as the draw and the pins do (docs/bridges.md).
     */
    public static final String LATCH_CATCH = "latch_catch";

    /** The MJCF text of {@code m}. */
    public static String of(RobotModel m) {
        return of(m, List.of());
    }

    /**
     * The MJCF text of {@code m} with the plate pairs {@code latches} as welds that start inactive,
     * four per pair (one per 90° step of the aligned pose, {@link Latches.Pair#weld}), and a site
     * per latchable plate (x its face's normal, y its "up"); a runner switches a weld on when the
     * pair latches and off when it is released (docs/bridges.md).
     */
    public static String of(RobotModel m, List<Latches.Pair> latches) {
        XmlOut x = new XmlOut();
        x.comment("PARPE robot '" + m.name() + "' (parpe export --target mjcf). Joints and actuators m<ID> are the"
                + " modules; a control is the module's angle in radians.");
        x.start("mujoco").attr("model", m.name());
        x.start("compiler").attr("angle", "radian").attr("inertiafromgeom", "false").end();
        // a 0.5 ms step: the stiff servo is stable (KP), and a closed loop (a soft constraint) stays within 1 mm
        // the implicit integrator: a servo's velocity feedback on a 40 g segment half is far too stiff for Euler's
        // MJCF has no actuator speed limit: the runner keeps the control within speed/gain of the angle (play_mujoco.py)
        x.start("custom");
        x.start("numeric").attr("name", SERVO_SPEED).attr("data", RobotModel.speed()).end();
        if (!latches.isEmpty()) {
            x.start("numeric").attr("name", LATCH_CATCH).attr("data", Docking.DRAW_DISTANCE, Docking.DRAW_ANGLE).end();
        }
        x.end();
        // Coulomb's cone, not MuJoCo's default pyramid: ODE's pyramid in PARPE gives mu along each floor axis and more
        // between them, MuJoCo's gives mu/sqrt(2) on the diagonals, the cone mu in every direction (docs/simulator.md)
        x.start("option").attr("timestep", STEP).attr("integrator", "implicit").attr("cone", "elliptic")
                .attr("gravity", 0, 0, -9.81).end();
        x.start("default");
        x.start("geom").attr("friction", RobotModel.selfFriction(), 0.005, 0.0001).attr("condim", "3").end();
        x.start("joint").attr("limited", "true").attr("range", -RobotModel.range(), RobotModel.range()).end();
        // PARPE's servo drives at g·(target − q) with at most its torque; as an MJCF position servo with velocity
        // feedback: force = kp·(ctrl − q) − kv·q̇, kv = kp / g, capped at the torque (a <general> actuator, the
        // form of <position kp kv> that MuJoCo 2.2 reads too)
        x.start("general").attr("gaintype", "fixed").attr("biastype", "affine").attr("gainprm", KP)
                .attr("biasprm", 0, -KP, -KP / RobotModel.gain()).attr("ctrllimited", "true")
                .attr("ctrlrange", -RobotModel.range(), RobotModel.range()).attr("forcelimited", "true")
                .attr("forcerange", -RobotModel.torque(), RobotModel.torque()).end();
        x.end();
        x.start("worldbody");
        x.start("light").attr("pos", 0, 0, 3).attr("dir", 0, 0, -1).end();
        x.start("geom").attr("name", "floor").attr("type", "plane").attr("size", 10, 10, 0.1)
                .attr("friction", RobotModel.groundFriction(), 0.005, 0.0001).end();
        body(x, m, m.root(), -1, plates(latches));
        x.end();
        if (!m.excluded().isEmpty()) {
            x.start("contact");
            for (int[] p : m.excluded()) {
                x.start("exclude").attr("body1", m.links().get(p[0]).name()).attr("body2", m.links().get(p[1]).name()).end();
            }
            x.end();
        }
        equality(x, m, latches);
        List<RobotModel.Joint> servos = servos(m);
        if (!servos.isEmpty()) {
            x.start("actuator");
            for (RobotModel.Joint j : servos) {
                x.start("general").attr("name", j.name()).attr("joint", j.name()).end();
            }
            x.end();
        }
        return x.toString();
    }

    /**
     * The robot's closed loops as welds, and the plate pairs {@code latches} as four inactive
     * welds each (one per 90° step of the aligned pose).
     */
    private static void equality(XmlOut x, RobotModel m, List<Latches.Pair> latches) {
        if (!m.closures().isEmpty() || !latches.isEmpty()) {
            x.start("equality");
            for (RobotModel.Closure c : m.closures()) {
                x.start("weld").attr("name", c.name()).attr("solref", 2 * STEP, 1).attr("body1", m.links().get(c.a()).name())
                        .attr("body2", m.links().get(c.b()).name()).end();
            }
            for (Latches.Pair p : latches) {
                for (int step = 0; step < 4; step++) {
                    Vec3 at = p.position(step);
                    double[] q = Frames.quaternion(p.rotation(step));
                    x.start("weld").attr("name", p.weld(step)).attr("active", "false").attr("solref", 2 * STEP, 1)
                            .attr("body1", m.links().get(p.a().link()).name()).attr("body2", m.links().get(p.b().link()).name())
                            .attr("relpose", at.x(), at.y(), at.z(), q[0], q[1], q[2], q[3]).end();
                }
            }
            x.end();
        }
    }

    /** The servo joints in ascending module ID, the order of a trace's columns. */
    static List<RobotModel.Joint> servos(RobotModel m) {
        List<RobotModel.Joint> out = new ArrayList<>(m.joints().stream().filter(RobotModel.Joint::revolute).toList());
        out.sort((a, b) -> Integer.compare(a.moduleId(), b.moduleId()));
        return out;
    }

    private static List<Latches.Plate> plates(List<Latches.Pair> latches) {
        List<Latches.Plate> out = new ArrayList<>();
        for (Latches.Pair p : latches) {
            for (Latches.Plate plate : List.of(p.a(), p.b())) {
                if (!out.contains(plate)) {
                    out.add(plate);
                }
            }
        }
        return out;
    }

    private static void body(XmlOut x, RobotModel m, int i, int parent, List<Latches.Plate> plates) {
        RobotModel.Link l = m.links().get(i);
        x.start("body").attr("name", l.name());
        Vec3 p = parent < 0 ? l.position() : m.relativePosition(parent, i);
        x.attr("pos", p.x(), p.y(), p.z());
        x.attr("quat", Frames.quaternion(parent < 0 ? l.rotation() : m.relativeRotation(parent, i)));
        if (parent < 0) {
            x.start("freejoint").attr("name", "root").end();
        }
        RobotModel.Joint j = m.jointOf(i);
        if (j != null && j.revolute()) {
            Vec3 at = m.local(i, j.anchor());
            Vec3 axis = m.localDirection(i, j.axis());
            x.start("joint").attr("name", j.name()).attr("type", "hinge").attr("pos", at.x(), at.y(), at.z())
                    .attr("axis", axis.x(), axis.y(), axis.z()).attr("ref", j.initial()).end();
        }
        Vec3 inertia = m.inertia(i);
        x.start("inertial").attr("pos", 0, 0, 0).attr("mass", l.mass()).attr("diaginertia", inertia.x(), inertia.y(),
                inertia.z()).end();
        geom(x, l.shape());
        if (m.axle() != null && m.axle().piece() == i) {
            // the runner judges a rolling robot's fall by this axis, as PARPE's metrics do (a rolling robot's root turns over)
            Vec3 a = m.axle().local();
            x.start("site").attr("name", AXLE).attr("zaxis", a.x(), a.y(), a.z()).end();
        }
        for (Latches.Plate plate : plates) {
            if (plate.link() == i) {
                Vec3 c = plate.centre();
                x.start("site").attr("name", plate.name()).attr("pos", c.x(), c.y(), c.z())
                        .attr("quat", Frames.quaternion(plate.frame())).end();
            }
        }
        for (RobotModel.Joint c : m.joints()) {
            if (c.parent() == i) {
                body(x, m, c.child(), i, plates);
            }
        }
        x.end();
    }

    private static void geom(XmlOut x, BodyShape shape) {
        x.start("geom");
        if (shape instanceof BodyShape.Box b) {
            x.attr("type", "box").attr("size", b.hx(), b.hy(), b.hz());
        } else if (shape instanceof BodyShape.Cylinder c) {
            x.attr("type", "cylinder").attr("size", c.radius(), c.length() / 2);
        } else {
            x.attr("type", "sphere").attr("size", ((BodyShape.Sphere) shape).radius());
        }
        x.end();
    }
}
