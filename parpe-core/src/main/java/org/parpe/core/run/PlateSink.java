package org.parpe.core.run;

import org.parpe.core.diag.SourcePos;

/**
 * Receives the plate actions of a tick (PARSL.md §14): the connection plates that modules arm
 * or release by entering states with {@code latch} or {@code unlatch}. Called on the engine
 * thread, only on ticks with at least one action, just before the tick's setpoints go to the
 * plants (the actions "take effect when the tick's setpoints are emitted"). The arrays are
 * reused: copy what is kept.
 */
@FunctionalInterface
public interface PlateSink {
    /** No action on that plate this tick. */
    byte NONE = 0;
    /** The plate is armed: it latches as soon as a plate it can join is within reach. */
    byte ARM = 1;
    /** The plate is disarmed and, if latched, released. */
    byte RELEASE = 2;

    /**
     * The actions of tick {@code tick}: {@code actions[2 * i + p]} is {@link #NONE}, {@link #ARM}
     * or {@link #RELEASE} for plate {@code p} of the module with index {@code i} (ascending ID
     * order); {@code where[2 * i + p]} is the state whose entry made the action (null where none).
     * Where two instances act on one plate in one tick, the later instance's action is given.
     */
    void plates(long tick, double time, byte[] actions, SourcePos[] where);
}
