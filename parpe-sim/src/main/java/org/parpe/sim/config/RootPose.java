package org.parpe.sim.config;

import org.parpe.core.diag.SourcePos;

/**
 * Where the root part is placed. The robot is then moved up or down so that its lowest point is
 * {@code height} above the ground (z = 0).
 *
 * @param part  name of the root part
 * @param x     x of the root part's origin, metres
 * @param y     y of the root part's origin, metres
 * @param roll  rotation about world x, degrees (applied first)
 * @param pitch rotation about world y, degrees (second)
 * @param yaw   rotation about world z, degrees (last)
 * @param height clearance of the robot's lowest point above the ground at the start, m
 * @param pos    where the {@code <root>} element is ({@link SourcePos#NONE} when the file has none
 *               or a generator made it); with its span when the file was read as text
 */
public record RootPose(String part, double x, double y, double roll, double pitch, double yaw, double height,
                       SourcePos pos) {

    /** A pose from no file. */
    public RootPose(String part, double x, double y, double roll, double pitch, double yaw, double height) {
        this(part, x, y, roll, pitch, yaw, height, SourcePos.NONE);
    }

    /** Resting on the ground (0.5 mm clearance). */
    public static final double RESTING = 0.0005;

    /** A pose resting on the ground. */
    public RootPose(String part, double x, double y, double roll, double pitch, double yaw) {
        this(part, x, y, roll, pitch, yaw, RESTING);
    }
}
