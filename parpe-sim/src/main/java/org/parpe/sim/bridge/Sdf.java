package org.parpe.sim.bridge;

import org.parpe.sim.geom.Vec3;

/**
 * A robot as SDF 1.7, for Gazebo: a model with a link per piece at the initial pose, a revolute
 * joint {@code m<ID>} per segment and a fixed joint per plate connection, the connections that
 * close loops included (SDF describes a joint graph, so loops need no special form). As in URDF,
 * a joint's value is the module's angle minus its initial angle.
 */
public final class Sdf {
    private Sdf() {
    }

    /** The SDF text of {@code m}. */
    public static String of(RobotModel m) {
        XmlOut x = new XmlOut();
        x.comment("PARPE robot '" + m.name() + "' (parpe export --target sdf). Joint m<ID> is module ID's servo;"
                + " its value is the module angle minus the initial angle, in radians.");
        x.start("sdf").attr("version", "1.7");
        x.start("model").attr("name", m.name());
        for (int i = 0; i < m.links().size(); i++) {
            link(x, m, i);
        }
        for (RobotModel.Joint j : m.joints()) {
            x.start("joint").attr("name", j.name()).attr("type", j.revolute() ? "revolute" : "fixed");
            x.text("parent", m.links().get(j.parent()).name());
            x.text("child", m.links().get(j.child()).name());
            if (j.revolute()) {
                Vec3 at = m.local(j.child(), j.anchor());
                Vec3 axis = m.localDirection(j.child(), j.axis());
                x.text("pose", at.x(), at.y(), at.z(), 0, 0, 0);
                x.start("axis");
                x.text("xyz", axis.x(), axis.y(), axis.z());
                x.start("limit");
                x.text("lower", -RobotModel.range() - j.initial());
                x.text("upper", RobotModel.range() - j.initial());
                x.text("effort", RobotModel.torque());
                x.text("velocity", RobotModel.speed());
                x.end();
                x.end();
            }
            x.end();
        }
        for (RobotModel.Closure c : m.closures()) {
            x.start("joint").attr("name", c.name()).attr("type", "fixed");
            x.text("parent", m.links().get(c.a()).name());
            x.text("child", m.links().get(c.b()).name());
            x.end();
        }
        x.end();
        return x.toString();
    }

    private static void link(XmlOut x, RobotModel m, int i) {
        RobotModel.Link l = m.links().get(i);
        x.start("link").attr("name", l.name());
        double[] rpy = Frames.rpy(l.rotation());
        x.text("pose", l.position().x(), l.position().y(), l.position().z(), rpy[0], rpy[1], rpy[2]);
        x.start("inertial");
        x.text("mass", l.mass());
        Vec3 in = m.inertia(i);
        x.start("inertia");
        x.text("ixx", in.x());
        x.text("ixy", 0);
        x.text("ixz", 0);
        x.text("iyy", in.y());
        x.text("iyz", 0);
        x.text("izz", in.z());
        x.end();
        x.end();
        x.start("collision").attr("name", "collision");
        geometry(x, l);
        x.start("surface");
        x.start("friction");
        x.start("ode");
        x.text("mu", RobotModel.groundFriction());
        x.text("mu2", RobotModel.groundFriction());
        x.end();
        x.end();
        x.end();
        x.end();
        x.start("visual").attr("name", "visual");
        geometry(x, l);
        x.end();
        x.end();
    }

    private static void geometry(XmlOut x, RobotModel.Link l) {
        x.start("geometry");
        if (l.shape() instanceof org.parpe.sim.geom.BodyShape.Box b) {
            x.start("box");
            x.text("size", 2 * b.hx(), 2 * b.hy(), 2 * b.hz());
            x.end();
        } else if (l.shape() instanceof org.parpe.sim.geom.BodyShape.Cylinder c) {
            x.start("cylinder");
            x.text("radius", c.radius());
            x.text("length", c.length());
            x.end();
        } else {
            x.start("sphere");
            x.text("radius", ((org.parpe.sim.geom.BodyShape.Sphere) l.shape()).radius());
            x.end();
        }
        x.end();
    }
}
