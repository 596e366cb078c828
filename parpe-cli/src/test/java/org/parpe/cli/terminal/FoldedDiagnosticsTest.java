package org.parpe.cli.terminal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.SourcePos;
import org.parpe.serial.bus.BusReport;
import org.parpe.serial.bus.HostPlant;

/**
 * A hardware run's diagnostics on the command line fold as the IDE's Problems view folds them
 * (docs/ide.md, Problems: equal run problems are one row with their count, {@code … (×3)}):
 * a servo stopping on its watchdog at every stall was one line per stop.
 */
class FoldedDiagnosticsTest {
    static final String STOPPED = "bus: servo 3 had stopped on its watchdog (a gap of more than 60 ms in the bus"
            + " traffic); resuming it";

    @Test
    void equalWarningsArePrintedOnceWhenTheyComeAndOnceWithTheirCountAtTheEnd() {
        List<String> lines = new ArrayList<>();
        FoldedDiagnostics folded = new FoldedDiagnostics(lines::add);
        BusReport bus = HostPlant.reportTo(SourcePos.origin("bus /dev/ttyUSB0"), folded, lines::add);
        for (int i = 0; i < 5; i++) {
            bus.problem(STOPPED);
        }
        bus.problem("bus: servo 4 had stopped on its watchdog (a gap of more than 60 ms in the bus traffic);"
                + " resuming it");
        folded.finish();
        String w = "bus /dev/ttyUSB0: warning: servo 3 had stopped on its watchdog (a gap of more than 60 ms in the bus"
                + " traffic); resuming it";
        assertEquals(List.of(w,
                "bus /dev/ttyUSB0: warning: servo 4 had stopped on its watchdog (a gap of more than 60 ms in the bus"
                        + " traffic); resuming it",
                w + "  (\u00d75)"), lines);
    }
}
