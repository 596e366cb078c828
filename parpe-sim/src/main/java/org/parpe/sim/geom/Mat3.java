package org.parpe.sim.geom;

/**
 * An immutable 3×3 rotation matrix, row-major: column {@code j} is the body's {@code j}-th
 * local axis expressed in world coordinates, so a local point {@code p} is at
 * {@code position + R·p} in the world.
 *
 * @param m00 row 0, column 0
 * @param m01 row 0, column 1
 * @param m02 row 0, column 2
 * @param m10 row 1, column 0
 * @param m11 row 1, column 1
 * @param m12 row 1, column 2
 * @param m20 row 2, column 0
 * @param m21 row 2, column 1
 * @param m22 row 2, column 2
 */
public record Mat3(double m00, double m01, double m02,
                   double m10, double m11, double m12,
                   double m20, double m21, double m22) {

    /** The identity rotation. */
    public static final Mat3 IDENTITY = new Mat3(1, 0, 0, 0, 1, 0, 0, 0, 1);

    /** Entry at {@code row}, {@code column} (0-based). */
    public double get(int row, int column) {
        return switch (row * 3 + column) {
            case 0 -> m00;
            case 1 -> m01;
            case 2 -> m02;
            case 3 -> m10;
            case 4 -> m11;
            case 5 -> m12;
            case 6 -> m20;
            case 7 -> m21;
            case 8 -> m22;
            default -> throw new IndexOutOfBoundsException("row " + row + ", column " + column);
        };
    }

    /** The body's local axis {@code column} (0 = x, 1 = y, 2 = z) in world coordinates. */
    public Vec3 axis(int column) {
        return new Vec3(get(0, column), get(1, column), get(2, column));
    }
}
