package org.parpe.core.run;

import java.util.Locale;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.text.Msg;

/**
 * The plate actions of a run on a robot without latching plates (PARSL.md §14): each action is
 * reported once per plate as a located warning that tells the user to join or part those plates
 * by hand; it is never silently ignored. Allocates only for a warning, at most four per module.
 */
public final class PlatesByHand implements PlateSink {
    private final DiagnosticSink warnings;
    private final int[] ids;
    private final String what;
    /** Per module and plate, the actions already reported (bit ARM, bit RELEASE). */
    private final byte[] told;

    /**
     * Reports to {@code warnings}; {@code ids} are the module IDs in ascending order and
     * {@code what} names the robot ("these servos", "the modules on /dev/ttyUSB0").
     */
    public PlatesByHand(DiagnosticSink warnings, int[] ids, String what) {
        this.warnings = warnings;
        this.ids = ids.clone();
        this.what = what;
        this.told = new byte[2 * ids.length];
    }

    @Override
    public void plates(long tick, double time, byte[] actions, SourcePos[] where) {
        for (int j = 0; j < actions.length; j++) {
            byte act = actions[j];
            if (act == NONE || (told[j] & act) != 0) {
                continue;
            }
            told[j] |= act;
            SourcePos at = where[j] == null ? SourcePos.origin("run") : where[j];
            warnings.warning(at, act == ARM ? Msg.ARMS_BY_HAND : Msg.RELEASES_BY_HAND,
                    String.format(Locale.ROOT, "%.3f", time), ids[j >> 1], j & 1, what);
        }
    }

    /** What the user does by hand for action {@code act} ({@link #ARM} or {@link #RELEASE}) on a plate. */
    public static String task(byte act) {
        return (act == ARM ? Msg.JOIN_BY_HAND : Msg.PART_BY_HAND).text();
    }
}
