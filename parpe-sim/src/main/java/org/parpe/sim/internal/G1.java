package org.parpe.sim.internal;

/**
 * PolyBot G1-like dimensions, masses and servo figures (SI units). The G1 segment is a hobby
 * servo in a laser-cut plastic frame with a 5 cm square connection plate at each end; these
 * numbers are documented, with their reasons, in {@code docs/simulator.md}.
 */
public final class G1 {
    private G1() {
    }

    /** Edge of a square connection plate, m. */
    public static final double PLATE = 0.05;
    /** Half the plate edge: half the width and height of a segment or node, m. */
    public static final double HALF = PLATE / 2;
    /** Distance between a segment's two plates, m (the hinge is in the middle). */
    public static final double SEGMENT_LENGTH = 0.06;
    /** Clearance each half leaves on its side of the hinge axis, m. */
    public static final double HINGE_CLEARANCE = 0.004;
    /** Mass of the servo half (plate 0), kg. */
    public static final double BASE_MASS = 0.060;
    /** Mass of the turning half (plate 1), kg. */
    public static final double ARM_MASS = 0.040;
    /** Edge of a node cube, m. */
    public static final double NODE_SIZE = 0.05;
    /** Mass of a node, kg. */
    public static final double NODE_MASS = 0.080;
    /** Foot pad: length away from its plate, m. */
    public static final double FOOT_LENGTH = 0.04;
    /** Foot pad: extent along its plate's "up" axis (the joint axis of an attached segment), m. */
    public static final double FOOT_WIDTH = 0.10;
    /** Mass of a foot, kg. */
    public static final double FOOT_MASS = 0.020;
    /** Thickness of a hub disc, m. */
    public static final double HUB_THICKNESS = 0.05;
    /** Smallest hub radius, m. */
    public static final double HUB_MIN_RADIUS = 0.035;
    /** Mass of a hub, kg. */
    public static final double HUB_MASS = 0.100;

    /** Servo speed limit, rad/s (about 300°/s, a fast analogue hobby servo at 6 V). */
    public static final double SERVO_SPEED = Math.toRadians(300);
    /** Servo torque limit, N·m (about 4 kg·cm). */
    public static final double SERVO_TORQUE = 0.4;
    /** Joint range, each side of zero, rad. */
    public static final double JOINT_RANGE = Math.toRadians(90);
    /** Proportional gain of the servo's position loop, 1/s. */
    public static final double SERVO_GAIN = 40;
    /** Holding torque of a limp servo (gear-train friction when back-driven), N·m. */
    public static final double LIMP_TORQUE = 0.004;

    /** Hub radius for {@code plates} plates round the rim: adjacent plates just do not overlap. */
    public static double hubRadius(int plates) {
        return Math.max(HUB_MIN_RADIUS, HALF / Math.tan(Math.PI / plates));
    }
}
