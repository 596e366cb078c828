package org.parpe.sim.geom;

/**
 * An immutable 3-vector in metres (positions) or a unit direction, world frame unless stated.
 * The world has {@code z} up and the ground plane at {@code z = 0}.
 *
 * @param x x component
 * @param y y component
 * @param z z component
 */
public record Vec3(double x, double y, double z) {

    /** The zero vector. */
    public static final Vec3 ZERO = new Vec3(0, 0, 0);

    /** Euclidean length. */
    public double length() {
        return Math.sqrt(x * x + y * y + z * z);
    }

    /** Whether every component is finite. */
    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }
}
