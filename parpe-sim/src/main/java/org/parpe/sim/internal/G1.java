package org.parpe.sim.internal;

/**
 * PolyBot G1-like dimensions, masses and servo figures (SI units: m, kg, rad, s, N·m). The G1
 * segment is a hobby servo in a laser-cut plastic frame with a 5 cm square connection plate at
 * each end; these numbers are documented, with their reasons, in {@code docs/simulator.md}.
 */
public final class G1 {
    private G1() {
    }

    /** Edge of a square connection plate, m. */
    public static final double PLATE = 0.05;
    /** Half the plate edge: half the width and height of a segment or node, m. */
    public static final double HALF = PLATE / 2;

    /**
     * A segment: two halves either side of its hinge, each as wide and high as a plate.
     *
     * @param length         distance between its two plates (the hinge is in the middle)
     * @param hingeClearance clearance each half leaves on its side of the hinge axis
     * @param baseMass       mass of the servo half (plate 0)
     * @param armMass        mass of the turning half (plate 1)
     */
    public record Segment(double length, double hingeClearance, double baseMass, double armMass) {
    }

    /**
     * A part without a joint: a node cube, a foot pad or a hub disc.
     *
     * @param length along its plate's normal: a node's edge, a foot's length away from its plate,
     *               a hub's thickness
     * @param width  a foot's extent along its plate's "up" axis (the joint axis of an attached
     *               segment), a hub's smallest radius; a node's edge
     * @param mass   its mass
     */
    public record Block(double length, double width, double mass) {
    }

    /**
     * The servo of a segment.
     *
     * @param speed      speed limit, rad/s (about 300°/s, a fast analogue hobby servo at 6 V)
     * @param torque     torque limit, N·m (about 4 kg·cm)
     * @param range      joint range, each side of zero, rad
     * @param gain       proportional gain of its position loop, 1/s
     * @param limpTorque holding torque when limp (gear-train friction when back-driven), N·m
     */
    public record Servo(double speed, double torque, double range, double gain, double limpTorque) {
    }

    public static final Segment SEGMENT = new Segment(0.06, 0.004, 0.060, 0.040);
    public static final Block NODE = new Block(0.05, 0.05, 0.080);
    public static final Block FOOT = new Block(0.04, 0.10, 0.020);
    public static final Block HUB = new Block(0.05, 0.035, 0.100);
    public static final Servo SERVO = new Servo(Math.toRadians(300), 0.4, Math.toRadians(90), 40, 0.004);

    /** Hub radius for {@code plates} plates round the rim: adjacent plates just do not overlap. */
    public static double hubRadius(int plates) {
        return Math.max(HUB.width(), HALF / Math.tan(Math.PI / plates));
    }
}
