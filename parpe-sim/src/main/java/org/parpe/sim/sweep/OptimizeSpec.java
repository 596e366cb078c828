package org.parpe.sim.sweep;

import org.parpe.sim.text.SimMsg;

/**
 * What an optimisation looks for.
 *
 * @param objective   what to maximise
 * @param constraints what a gait must meet; runs that miss are ranked below every run that meets them
 * @param budget      the most simulations, >= 2 per start
 * @param starts      independent CMA-ES searches sharing the budget, run in parallel; the result
 *                    depends on this number, never on the number of threads
 * @param seed        the seed of CMA-ES's random numbers and of the script's {@code rand()}
 */
public record OptimizeSpec(Objective objective, Constraints constraints, int budget, int starts, long seed) {

    /** Checks the numbers; one line per problem. */
    public void check() throws SweepException {
        if (starts < 1) {
            throw new SweepException(SimMsg.STARTS_AT_LEAST_ONE, starts);
        }
        if (budget < 2 * starts) {
            throw new SweepException(SimMsg.BUDGET_TOO_SMALL, 2 * starts, budget);
        }
    }
}
