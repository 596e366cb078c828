package org.parpe.sim.geom;

/**
 * The collision and drawing shape of one rigid piece, centred on the piece's position and
 * expressed in its local frame. Lengths in metres.
 */
public sealed interface BodyShape {

    /**
     * A box.
     *
     * @param hx half extent along local x
     * @param hy half extent along local y
     * @param hz half extent along local z
     */
    record Box(double hx, double hy, double hz) implements BodyShape {
    }

    /**
     * A solid cylinder whose axis is the local z axis.
     *
     * @param radius radius
     * @param length length along local z
     */
    record Cylinder(double radius, double length) implements BodyShape {
    }

    /**
     * A sphere.
     *
     * @param radius radius
     */
    record Sphere(double radius) implements BodyShape {
    }
}
