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
 * @param warmStart        what part of the step before's constraint forces each solver row starts
 *                         from (joints' rows from their own, contacts' from the same contact's):
 *                         0 starts from zero as ODE4j does; 0.9 converges the standard gaits in 10
 *                         iterations ({@code org.ode4j.ode.internal.WarmStart}; docs/decisions.md,
 *                         "PARPE's step and the MuJoCo cross-check")
 */
public record PhysicsParams(double maxSubstep, int iterations, double groundFriction, double selfFriction,
                            double softErp, double softCfm, int contactsPerPair, double warmStart) {

    /** The settings used unless a test asks for others (warm starting off: see docs/decisions.md). */
    public static PhysicsParams defaults() {
        // 5 ms steps, 10 solver iterations and two contact points per touching pair: the
        // cheapest settings measured to keep the standard gaits (snake, wheel, centipede)
        // moving reliably; 10 ms steps run twice as fast but make the wheel gait erratic.
        return new PhysicsParams(0.005, 10, 0.6, 0.3, 0.3, 1e-4, 2, 0);
    }

    /** These settings with the solver's rows warm-started from {@code part} of the step before's forces. */
    public PhysicsParams withWarmStart(double part) {
        return new PhysicsParams(maxSubstep, iterations, groundFriction, selfFriction, softErp, softCfm, contactsPerPair, part);
    }

    /** These settings with {@code n} solver iterations per sub-step. */
    public PhysicsParams withIterations(int n) {
        return new PhysicsParams(maxSubstep, n, groundFriction, selfFriction, softErp, softCfm, contactsPerPair, warmStart);
    }
}
