package org.parpe.cli.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/**
 * The export benchmark reads the C program's CPU time from the shell's {@code times} (POSIX, "times":
 * "the accumulated user and system times for the shell and for all of its child processes", each as
 * minutes, {@code m}, seconds and {@code s}; the children's on the second line).
 */
class ExportBenchmarkTest {
    @Test
    void theChildrensUserAndSystemTimeAreAdded() {
        assertEquals(0.356, ExportBenchmark.cpuSeconds("0m0.352000s 0m0.004000s"), 1e-12);
        assertEquals(62.5, ExportBenchmark.cpuSeconds("1m2.25s 0m0.25s"), 1e-12);
    }

    @Test
    void aLineWithoutTwoTimesIsAnError() {
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> ExportBenchmark.cpuSeconds("sh: times: not found"));
        assertEquals("the shell's times printed 'sh: times: not found', not a user and a system time", e.getMessage());
    }
}
