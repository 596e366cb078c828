package org.parpe.sim.config;

import org.parpe.core.diag.SourcePos;

/**
 * Two plates bolted together. The second part is placed so that its plate faces the first
 * plate, centres coinciding, and its plate's "up" direction is the first plate's "up" turned
 * by {@code quarterTurns} × 90° (right-handed) about the first plate's outward normal.
 *
 * @param from         name of the first part
 * @param fromPlate    plate index on the first part
 * @param to           name of the second part
 * @param toPlate      plate index on the second part
 * @param quarterTurns orientation, 0 to 3 (0°, 90°, 180°, 270°)
 * @param pos          where the connection is defined
 */
public record Connection(String from, int fromPlate, String to, int toPlate, int quarterTurns,
                         SourcePos pos) {

    /** A connection made by a generator. */
    public static Connection of(String from, int fromPlate, String to, int toPlate, int quarterTurns) {
        return new Connection(from, fromPlate, to, toPlate, quarterTurns, SourcePos.NONE);
    }
}
