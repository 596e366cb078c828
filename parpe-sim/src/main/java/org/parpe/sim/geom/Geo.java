package org.parpe.sim.geom;


/** Small vector and rotation helpers used while building a robot (not in the tick loop). */
public final class Geo {
    private Geo() {
    }

    public static Vec3 add(Vec3 a, Vec3 b) {
        return new Vec3(a.x() + b.x(), a.y() + b.y(), a.z() + b.z());
    }

    public static Vec3 sub(Vec3 a, Vec3 b) {
        return new Vec3(a.x() - b.x(), a.y() - b.y(), a.z() - b.z());
    }

    public static Vec3 scale(Vec3 a, double s) {
        return new Vec3(a.x() * s, a.y() * s, a.z() * s);
    }

    public static double dot(Vec3 a, Vec3 b) {
        return a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
    }

    public static Vec3 cross(Vec3 a, Vec3 b) {
        return new Vec3(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(),
                a.x() * b.y() - a.y() * b.x());
    }

    /** {@code m·v}. */
    public static Vec3 mul(Mat3 m, Vec3 v) {
        return new Vec3(m.m00() * v.x() + m.m01() * v.y() + m.m02() * v.z(),
                m.m10() * v.x() + m.m11() * v.y() + m.m12() * v.z(),
                m.m20() * v.x() + m.m21() * v.y() + m.m22() * v.z());
    }

    /** {@code a·b}. */
    public static Mat3 mul(Mat3 a, Mat3 b) {
        double[] r = new double[9];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                r[i * 3 + j] = a.get(i, 0) * b.get(0, j) + a.get(i, 1) * b.get(1, j) + a.get(i, 2) * b.get(2, j);
            }
        }
        return of(r);
    }

    public static Mat3 transpose(Mat3 m) {
        return new Mat3(m.m00(), m.m10(), m.m20(), m.m01(), m.m11(), m.m21(), m.m02(), m.m12(), m.m22());
    }

    /** The matrix whose columns are {@code a}, {@code b}, {@code c}. */
    public static Mat3 columns(Vec3 a, Vec3 b, Vec3 c) {
        return new Mat3(a.x(), b.x(), c.x(), a.y(), b.y(), c.y(), a.z(), b.z(), c.z());
    }

    /** A row-major matrix from 9 numbers. */
    public static Mat3 of(double[] r) {
        return new Mat3(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]);
    }

    /** Right-handed rotation by {@code angle} radians about the unit vector {@code axis}. */
    public static Mat3 axisAngle(Vec3 axis, double angle) {
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        double t = 1 - c;
        double x = axis.x();
        double y = axis.y();
        double z = axis.z();
        return new Mat3(t * x * x + c, t * x * y - s * z, t * x * z + s * y,
                t * x * y + s * z, t * y * y + c, t * y * z - s * x,
                t * x * z - s * y, t * y * z + s * x, t * z * z + c);
    }

    /** Rotation about local z by {@code angle} radians. */
    public static Mat3 rotZ(double angle) {
        return axisAngle(new Vec3(0, 0, 1), angle);
    }

    /** Roll about x, then pitch about y, then yaw about z (degrees), as one rotation. */
    public static Mat3 rollPitchYaw(double rollDeg, double pitchDeg, double yawDeg) {
        Mat3 roll = axisAngle(new Vec3(1, 0, 0), Math.toRadians(rollDeg));
        Mat3 pitch = axisAngle(new Vec3(0, 1, 0), Math.toRadians(pitchDeg));
        Mat3 yaw = axisAngle(new Vec3(0, 0, 1), Math.toRadians(yawDeg));
        return mul(yaw, mul(pitch, roll));
    }

    /** Snaps components within 1e−12 of an integer to it, so generated poses stay exact. */
    public static Mat3 clean(Mat3 m) {
        double[] r = new double[9];
        for (int i = 0; i < 9; i++) {
            double v = m.get(i / 3, i % 3);
            double k = Math.rint(v);
            r[i] = Math.abs(v - k) < 1e-12 ? k : v;
        }
        return of(r);
    }

    /** The angle of the rotation taking {@code a} to {@code b}, radians. */
    public static double angleBetween(Mat3 a, Mat3 b) {
        Mat3 d = mul(transpose(a), b);
        double cos = (d.m00() + d.m11() + d.m22() - 1) / 2;
        return Math.acos(Math.max(-1, Math.min(1, cos)));
    }
}
