package org.parpe.core.run;

import java.util.List;

/**
 * How to run a program.
 *
 * @param dt       tick length in seconds (PARSL.md §11; default 0.01)
 * @param seed     seed of {@code rand()}
 * @param stimuli  timed control and sensor assignments (§11), in file order
 */
public record RunOptions(double dt, long seed, List<Stimulus> stimuli) {

    public RunOptions {
        if (!(dt > 0) || !Double.isFinite(dt)) {
            throw new IllegalArgumentException("tick must be > 0 seconds, got " + dt);
        }
        stimuli = List.copyOf(stimuli);
    }

    /** A 0.01 s tick, seed 0, no stimuli. */
    public static RunOptions defaults() {
        return new RunOptions(0.01, 0, List.of());
    }

}
