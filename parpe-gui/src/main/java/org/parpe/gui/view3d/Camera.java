package org.parpe.gui.view3d;

/**
 * An orbiting perspective camera in the simulator's world frame ({@code z} up): it looks at a
 * target point from a yaw angle (around {@code z}), a pitch angle (above the ground plane) and
 * a distance. {@link #update} fixes the basis for a frame; {@link #toCamera} then maps world
 * points to camera coordinates (x right, y up, z depth).
 */
public final class Camera {
    // Not lower than 10°: a drag that misses the robot must not end in a ground-level view
    // where the robot is a line.
    private static final double MIN_PITCH = Math.toRadians(10);
    static final double HOME_YAW = Math.toRadians(-60);
    static final double HOME_PITCH = Math.toRadians(30);
    private static final double MAX_PITCH = Math.toRadians(89);

    double yaw = HOME_YAW;
    double pitch = HOME_PITCH;
    double distance = 1.6;
    final double[] target = {0, 0, 0.05};
    private final double fov = Math.toRadians(45);

    private final double[] eye = new double[3];
    private final double[] right = new double[3];
    private final double[] up = new double[3];
    private final double[] forward = new double[3];
    private double focal;
    private double cx;
    private double cy;

    /** Back to the angle the view starts with (Reset view, double-click). */
    public void resetAngles() {
        yaw = HOME_YAW;
        pitch = HOME_PITCH;
    }

    /** Orbits by the given angles, radians. */
    public void rotate(double dYaw, double dPitch) {
        yaw += dYaw;
        pitch = Math.max(MIN_PITCH, Math.min(MAX_PITCH, pitch + dPitch));
    }

    /** Moves closer ({@code factor} &lt; 1) or further away. */
    public void zoom(double factor) {
        distance = Math.max(0.1, Math.min(50, distance * factor));
    }

    /** Moves the target in the camera's plane by a fraction of the distance. */
    public void pan(double dx, double dy) {
        for (int i = 0; i < 3; i++) {
            target[i] += (-dx * right[i] + dy * up[i]) * distance;
        }
        target[2] = Math.max(-1, target[2]);
    }

    /** Moves the target a part {@code alpha} of the way towards a point (tracking). */
    public void follow(double x, double y, double z, double alpha) {
        target[0] += (x - target[0]) * alpha;
        target[1] += (y - target[1]) * alpha;
        target[2] += (z - target[2]) * alpha;
    }

    /** Sets the target. */
    public void lookAt(double x, double y, double z) {
        target[0] = x;
        target[1] = y;
        target[2] = z;
    }

    /** Sets the distance to the target. */
    public void setDistance(double d) {
        distance = Math.max(0.1, Math.min(50, d));
    }

    /** The distance to the target. */
    public double distance() {
        return distance;
    }

    /** Fixes the basis and projection for a viewport of {@code width} × {@code height} pixels. */
    public void update(int width, int height) {
        double cp = Math.cos(pitch);
        eye[0] = target[0] + distance * cp * Math.cos(yaw);
        eye[1] = target[1] + distance * cp * Math.sin(yaw);
        eye[2] = target[2] + distance * Math.sin(pitch);
        for (int i = 0; i < 3; i++) {
            forward[i] = target[i] - eye[i];
        }
        normalize(forward);
        right[0] = forward[1];
        right[1] = -forward[0];
        right[2] = 0;
        normalize(right);
        up[0] = right[1] * forward[2] - right[2] * forward[1];
        up[1] = right[2] * forward[0] - right[0] * forward[2];
        up[2] = right[0] * forward[1] - right[1] * forward[0];
        focal = (height / 2.0) / Math.tan(fov / 2);
        cx = width / 2.0;
        cy = height / 2.0;
    }

    /** Writes the camera coordinates of world point (x, y, z) to {@code out}. */
    public void toCamera(double x, double y, double z, double[] out) {
        double dx = x - eye[0];
        double dy = y - eye[1];
        double dz = z - eye[2];
        out[0] = dx * right[0] + dy * right[1] + dz * right[2];
        out[1] = dx * up[0] + dy * up[1] + dz * up[2];
        out[2] = dx * forward[0] + dy * forward[1] + dz * forward[2];
    }

    /** Screen x of a camera-space point with depth {@code z} &gt; 0. */
    public double screenX(double x, double z) {
        return cx + focal * x / z;
    }

    /** Screen y of a camera-space point with depth {@code z} &gt; 0. */
    public double screenY(double y, double z) {
        return cy - focal * y / z;
    }

    /** Pixels per metre at depth {@code z}. */
    public double scale(double z) {
        return focal / z;
    }

    /** The eye position. */
    public double[] eye() {
        return eye;
    }

    private static void normalize(double[] v) {
        double l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (l > 1e-12) {
            v[0] /= l;
            v[1] /= l;
            v[2] /= l;
        }
    }
}
