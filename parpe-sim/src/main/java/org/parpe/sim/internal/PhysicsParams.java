package org.parpe.sim.internal;

/**
 * Numerical and contact settings of the physics world.
 *
 * @param maxSubstep       longest physics step, s; each tick is cut into equal sub-steps no longer
 * @param iterations       iterations of ODE's QuickStep solver per sub-step
 * @param groundFriction   Coulomb friction between a part and the floor (plastic on a smooth floor)
 * @param selfFriction     friction between two parts of the robot (plastic on plastic)
 * @param softErp          contact error reduction
 * @param softCfm          contact constraint force mixing (softness)
 * @param contactsPerPair  contact points kept per pair of touching pieces
 */
public record PhysicsParams(double maxSubstep, int iterations, double groundFriction, double selfFriction,
                            double softErp, double softCfm, int contactsPerPair) {

    /** The settings used unless a test asks for others. */
    public static PhysicsParams defaults() {
        // 5 ms steps, 10 solver iterations and two contact points per touching pair: the
        // cheapest settings measured to keep the standard gaits (snake, wheel, centipede)
        // moving reliably; 10 ms steps run twice as fast but make the wheel gait erratic.
        return new PhysicsParams(0.005, 10, 0.6, 0.3, 0.3, 1e-4, 2);
    }
}
