package org.parpe.sim.bridge;

import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;

/**
 * A robot as URDF, for ROS tools: a link per piece with its inertia, collision and visual box
 * (or cylinder), a revolute joint {@code m<ID>} per segment and a fixed joint per connection of
 * the tree. URDF joints have no reference angle: a joint's value is the module's angle minus its
 * initial angle (0 for most robots), and its limits are shifted the same way. A connection that
 * closes a loop cannot be a URDF joint; it is written, as ROS tools and Gazebo expect, as a fixed
 * SDF joint in a {@code <gazebo>} block, which Gazebo simulates and other ROS tools ignore.
 */
public final class Urdf {
    private Urdf() {
    }

    /** The URDF text of {@code m}. */
    public static String of(RobotModel m) {
        // a URDF link's frame is its joint's frame: on the hinge axis for a servo's child, else the piece centre
        Vec3[] origin = new Vec3[m.links().size()];
        for (int i = 0; i < origin.length; i++) {
            RobotModel.Joint j = m.jointOf(i);
            origin[i] = j != null && j.revolute() ? j.anchor() : m.links().get(i).position();
        }
        XmlOut x = new XmlOut();
        x.comment("PARPE robot '" + m.name() + "' (parpe export --target urdf). Joint m<ID> is module ID's servo;"
                + " its value is the module angle minus the initial angle, in radians.");
        x.start("robot").attr("name", m.name());
        for (int i = 0; i < m.links().size(); i++) {
            link(x, m, i, Geo.mul(Geo.transpose(m.links().get(i).rotation()), Geo.sub(m.links().get(i).position(), origin[i])));
        }
        for (RobotModel.Joint j : m.joints()) {
            joint(x, m, j, origin);
        }
        if (!m.closures().isEmpty()) {
            x.start("gazebo");
            for (RobotModel.Closure c : m.closures()) {
                // the pose of an SDF joint is given in the child link's frame: the connection is at the child's origin side
                x.start("joint").attr("name", c.name()).attr("type", "fixed");
                x.text("parent", m.links().get(c.a()).name());
                x.text("child", m.links().get(c.b()).name());
                x.text("pose", 0, 0, 0, 0, 0, 0);
                x.end();
            }
            x.end();
        }
        return x.toString();
    }

    /** Link {@code i}, its piece's centre at {@code centre} in the link frame. */
    private static void link(XmlOut x, RobotModel m, int i, Vec3 centre) {
        RobotModel.Link l = m.links().get(i);
        Vec3 inertia = m.inertia(i);
        x.start("link").attr("name", l.name());
        x.start("inertial");
        x.start("origin").attr("xyz", centre.x(), centre.y(), centre.z()).attr("rpy", 0, 0, 0).end();
        x.start("mass").attr("value", l.mass()).end();
        x.start("inertia").attr("ixx", inertia.x()).attr("ixy", 0).attr("ixz", 0).attr("iyy", inertia.y())
                .attr("iyz", 0).attr("izz", inertia.z()).end();
        x.end();
        for (String kind : new String[] {"collision", "visual"}) {
            x.start(kind);
            x.start("origin").attr("xyz", centre.x(), centre.y(), centre.z()).attr("rpy", 0, 0, 0).end();
            x.start("geometry");
            shape(x, l.shape());
            x.end();
            x.end();
        }
        x.end();
    }

    static void shape(XmlOut x, BodyShape shape) {
        if (shape instanceof BodyShape.Box b) {
            x.start("box").attr("size", 2 * b.hx(), 2 * b.hy(), 2 * b.hz()).end();
        } else if (shape instanceof BodyShape.Cylinder c) {
            x.start("cylinder").attr("radius", c.radius()).attr("length", c.length()).end();
        } else {
            x.start("sphere").attr("radius", ((BodyShape.Sphere) shape).radius()).end();
        }
    }

    private static void joint(XmlOut x, RobotModel m, RobotModel.Joint j, Vec3[] origin) {
        x.start("joint").attr("name", j.name()).attr("type", j.revolute() ? "revolute" : "fixed");
        Mat3 parent = m.links().get(j.parent()).rotation();
        Vec3 p = Geo.mul(Geo.transpose(parent), Geo.sub(origin[j.child()], origin[j.parent()]));
        x.start("origin").attr("xyz", p.x(), p.y(), p.z()).attr("rpy", Frames.rpy(m.relativeRotation(j.parent(), j.child())))
                .end();
        x.start("parent").attr("link", m.links().get(j.parent()).name()).end();
        x.start("child").attr("link", m.links().get(j.child()).name()).end();
        if (j.revolute()) {
            Vec3 axis = m.localDirection(j.child(), j.axis());
            x.start("axis").attr("xyz", axis.x(), axis.y(), axis.z()).end();
            x.start("limit").attr("lower", -RobotModel.range() - j.initial()).attr("upper", RobotModel.range() - j.initial())
                    .attr("effort", RobotModel.torque()).attr("velocity", RobotModel.speed()).end();
        }
        x.end();
    }
}
