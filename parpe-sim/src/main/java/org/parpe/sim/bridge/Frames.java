package org.parpe.sim.bridge;

import org.parpe.sim.geom.Mat3;

/** Orientations as the formats write them: MJCF's quaternions (w x y z), URDF's and SDF's roll, pitch and yaw. */
final class Frames {
    private Frames() {
    }

    /** The unit quaternion {@code w, x, y, z} of rotation {@code r}, with {@code w ≥ 0}. */
    static double[] quaternion(Mat3 r) {
        double tr = r.m00() + r.m11() + r.m22();
        double w;
        double x;
        double y;
        double z;
        if (tr > 0) {
            double s = Math.sqrt(tr + 1) * 2;
            w = s / 4;
            x = (r.m21() - r.m12()) / s;
            y = (r.m02() - r.m20()) / s;
            z = (r.m10() - r.m01()) / s;
        } else if (r.m00() > r.m11() && r.m00() > r.m22()) {
            double s = Math.sqrt(1 + r.m00() - r.m11() - r.m22()) * 2;
            w = (r.m21() - r.m12()) / s;
            x = s / 4;
            y = (r.m01() + r.m10()) / s;
            z = (r.m02() + r.m20()) / s;
        } else if (r.m11() > r.m22()) {
            double s = Math.sqrt(1 + r.m11() - r.m00() - r.m22()) * 2;
            w = (r.m02() - r.m20()) / s;
            x = (r.m01() + r.m10()) / s;
            y = s / 4;
            z = (r.m12() + r.m21()) / s;
        } else {
            double s = Math.sqrt(1 + r.m22() - r.m00() - r.m11()) * 2;
            w = (r.m10() - r.m01()) / s;
            x = (r.m02() + r.m20()) / s;
            y = (r.m12() + r.m21()) / s;
            z = s / 4;
        }
        double norm = Math.sqrt(w * w + x * x + y * y + z * z) * (w < 0 ? -1 : 1);
        return new double[] {w / norm, x / norm, y / norm, z / norm};
    }

    /**
     * Roll, pitch and yaw of {@code r} = Rz(yaw)·Ry(pitch)·Rx(roll), the convention of URDF's
     * {@code rpy} and SDF's poses.
     */
    static double[] rpy(Mat3 r) {
        double pitch = Math.asin(Math.max(-1, Math.min(1, -r.m20())));
        double roll;
        double yaw;
        if (Math.abs(r.m20()) < 1 - 1e-12) {
            roll = Math.atan2(r.m21(), r.m22());
            yaw = Math.atan2(r.m10(), r.m00());
        } else {
            // gimbal lock: all of the turn about x folded into yaw
            roll = 0;
            yaw = Math.atan2(-r.m01(), r.m11());
        }
        return new double[] {roll, pitch, yaw};
    }
}
