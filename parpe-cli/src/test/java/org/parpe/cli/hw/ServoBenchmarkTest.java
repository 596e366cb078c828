package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The servo cycle benchmark runs and prints its keys; its figures are measurements, not asserted. */
class ServoBenchmarkTest {
    @Test
    void cycleBenchmarkPrintsEveryKey() throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        new ServoBenchmark(0.05, true).run(new PrintStream(bytes, true, StandardCharsets.UTF_8));
        String out = bytes.toString(StandardCharsets.UTF_8);
        for (String p : new String[] {"dxl2", "sts", "scs"}) {
            for (int n : new int[] {18, 55}) {
                for (String k : new String[] {"bytes_per_cycle", "cycle_fps", "wire_limit_fps", "fraction",
                    "cpu_us_per_cycle", "cpu_us_per_cycle_max", "timeouts"}) {
                    assertTrue(out.contains("servo." + p + ".n" + n + "." + k + "="), () -> k + " missing in\n" + out);
                }
            }
        }
        // The bytes of a cycle are fixed by the protocols: a wrong count would mean a wrong limit.
        assertTrue(out.contains("servo.dxl2.n18.bytes_per_cycle=406\n"), out);
        assertEquals(42, out.lines().count());
    }
}
