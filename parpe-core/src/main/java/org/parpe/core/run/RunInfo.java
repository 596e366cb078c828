package org.parpe.core.run;

import org.parpe.core.model.Program;

/**
 * What a sink learns when a run starts.
 *
 * @param program   the program being run
 * @param moduleIds the robot's module IDs, ascending; setpoint arrays follow this order
 * @param dt        tick length, seconds
 */
public record RunInfo(Program program, int[] moduleIds, double dt) {
}
