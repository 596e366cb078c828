package org.parpe.sim.config;

/**
 * Where the root part is placed. The robot is then lifted so that its lowest point rests just
 * above the ground (z = 0), so no height is given.
 *
 * @param part  name of the root part
 * @param x     x of the root part's origin, metres
 * @param y     y of the root part's origin, metres
 * @param roll  rotation about world x, degrees (applied first)
 * @param pitch rotation about world y, degrees (second)
 * @param yaw   rotation about world z, degrees (last)
 */
public record RootPose(String part, double x, double y, double roll, double pitch, double yaw) {
}
