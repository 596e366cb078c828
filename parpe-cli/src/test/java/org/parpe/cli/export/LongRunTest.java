package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;

/**
 * A board whose {@code double} is a 32-bit float (AVR) keeps time over days (issue 21 item 7):
 * the exported C, compiled by gcc as an AVR compiler sees it ({@code real32.h}: {@code double}
 * is {@code float}, constants too) runs a gait for a simulated week at a 10 ms tick and a
 * sequence of timed entries for a week at 0.1 s, and its {@code $cycle}, {@code $phase},
 * {@code $time}, {@code $btime} and running entry are compared with the exact values, computed
 * here in integers (not by the code under test). Before the runtime counted time in integers,
 * {@code $cycle} was 164 cycles short after a day and stopped at 262 144 (73 h), and timed
 * entries drifted by whole ticks; a one-state wave summed its progress in a float and fell behind.
 * About 5 s.
 */
class LongRunTest {
    static final Path REAL32 = Path.of("src/test/resources/export/real32").toAbsolutePath();
    static final long DAY = 86_400;
    /**
     * The bound on the gait's phase error, in cycles per cycle run: the period and the tick are
     * floats (each within 2^-24 of the script's decimal), and every tick's progress is rounded
     * once more. Measured: 6e-8 (5 ms a day); a 16 MHz crystal is allowed 50e-6.
     */
    static final double RATE_BOUND = 1.5e-7;

    @TempDir
    Path tmp;

    @BeforeAll
    static void compilerInstalled() {
        HostCompiler.require("gcc");
    }

    /**
     * Period 0.997 s (a cycle boundary seldom falls on a tick), offset 0.25: at tick n the exact
     * progress is 10n/997 cycles from the start 3/4. $cycle must equal floor(10n/997) wherever the
     * exact progress is further than the phase bound from a whole cycle (88 % of the samples),
     * $phase be within that bound, on every sample of a week, past the 73 h where a float stops
     * counting.
     */
    @Test
    void aGaitCountsItsCyclesForAWeek() throws Exception {
        Path script = tmp.resolve("gait.xml");
        Files.writeString(script, "<program>\n<robot><structure><leg elements=\"0\"/></structure></robot>\n"
                + "<main><go/></main>\n<behaviors><go><walk group=\"leg\" period=\"0.997\" offset=\"0.25\"/></go></behaviors>\n"
                + "<automata><walk states=\"up, down\"/></automata>\n"
                + "<states><up angles=\"30\"/><down angles=\"-30\"/></states>\n</program>\n");
        long ticks = 7 * DAY * 100;
        List<double[]> rows = run(script, 0.01, ticks, 9973);
        int checked = 0;
        for (double[] row : rows) {
            long n = (long) row[0];
            long num = 10 * n; // progress since the start: num / 997 cycles
            long cycles = num / 997;
            long frac = num % 997;
            double bound = RATE_BOUND * (cycles + 1) + 1e-6;
            double exactPhase = ((3 * 997 + 4 * num) % (4 * 997)) / (4.0 * 997);
            double dPhase = Math.abs(row[2] - exactPhase);
            dPhase = Math.min(dPhase, 1 - dPhase);
            assertTrue(dPhase <= bound, () -> "tick " + n + ": $phase " + row[2] + ", exactly " + exactPhase
                    + ", more than " + bound + " apart");
            if (frac / 997.0 > bound && frac / 997.0 < 1 - bound) {
                checked++;
                assertEquals(cycles, (long) row[1], () -> "tick " + n + " (" + n / 360_000.0 + " h): $cycle");
            }
        }
        assertTrue(checked >= 0.8 * rows.size(), "cycles checked on " + checked + " of " + rows.size() + " samples");
        assertEquals(ticks, (long) rows.get(rows.size() - 1)[0]);
    }

    /**
     * A wave of one state and 1 s ($phase drives the angle) at a 10 ms tick: at tick n the exact
     * phase is (n mod 100)/100 and the angle 30*sin(2*pi*phase). Summing the step 0.01 into a
     * float rounded the same way every tick: 0.002 cycles (0.43 degrees) behind after an hour,
     * 0.06 after a day.
     */
    @Test
    void aPhaseWaveKeepsItsPhaseForADay() throws Exception {
        Path script = tmp.resolve("wave.xml");
        Files.writeString(script, "<program>\n<robot><structure><leg elements=\"0\"/></structure></robot>\n"
                + "<main><go/></main>\n<behaviors><go><wave group=\"leg\" period=\"1\"/></go></behaviors>\n"
                + "<automata><wave states=\"s\"/></automata>\n"
                + "<states><s angles=\"30*sin(2*pi*$phase)\" interp=\"step\"/></states>\n</program>\n");
        for (double[] row : run(script, 0.01, DAY * 100, 997)) {
            long n = (long) row[0];
            double exact = (n % 100) / 100.0;
            double d = Math.abs(row[2] - exact);
            double dPhase = Math.min(d, 1 - d);
            assertTrue(dPhase <= 1e-6, () -> "tick " + n + ": $phase " + row[2] + ", exactly " + exact);
            assertEquals(30 * Math.sin(2 * Math.PI * exact), row[6], 1e-3, () -> "tick " + n + ": angle");
            if (n % 100 != 0) { // on a whole cycle either count is right within a float
                assertEquals(n / 100, (long) row[1], () -> "tick " + n + ": $cycle");
            }
        }
    }

    /**
     * Entries of 1.2 s and 0.7 s repeated for a week at a tick of 0.1 s: each tick runs the entry
     * and has the $btime of the exact schedule (19 ticks a round), $btime and $time are the exact
     * decimal rounded to a float (within half a unit in the last place, plus 2^-23 s for the
     * fraction of the second, multiplied by the rounded 1/10 in parsl_rt.c).
     */
    @Test
    void timedEntriesKeepTheirScheduleForAWeek() throws Exception {
        Path script = tmp.resolve("entries.xml");
        Files.writeString(script, "<program>\n<robot><structure><leg elements=\"0\"/></structure></robot>\n"
                + "<main cycles=\"forever\"><lift time=\"1.2\"/><drop time=\"0.7\"/></main>\n"
                + "<behaviors><lift><swing group=\"leg\"/></lift><drop><swing group=\"leg\" period=\"0.5\"/></drop></behaviors>\n"
                + "<automata><swing states=\"up, down\"/></automata>\n"
                + "<states><up angles=\"30\"/><down angles=\"-30\"/></states>\n</program>\n");
        long ticks = 7 * DAY * 10;
        for (double[] row : run(script, 0.1, ticks, 997)) {
            long n = (long) row[0];
            long m = n % 19;
            int entry = m < 12 ? 0 : 1;
            long inEntry = m < 12 ? m : m - 12;
            assertEquals(entry, (int) row[5], () -> "tick " + n + ": running entry");
            assertCloseToDecimal(n, "$btime", row[4], inEntry);
            assertCloseToDecimal(n, "$time", row[3], n);
        }
    }

    /** {@code got} is {@code tenths}/10 s rounded to a float, within half an ulp plus 2^-23 s. */
    private static void assertCloseToDecimal(long n, String what, double got, long tenths) {
        BigDecimal exact = BigDecimal.valueOf(tenths, 1);
        float rounded = exact.floatValue();
        double err = new BigDecimal(got).subtract(exact).abs().doubleValue();
        double bound = Math.ulp(rounded) / 2 + 0x1p-23;
        assertTrue(err <= bound, () -> "tick " + n + ": " + what + " " + got + ", exactly " + exact + " (as a float "
                + rounded + "), " + err + " s apart, more than " + bound);
    }

    /** Exports {@code script} with {@code tick}, compiles it in 32-bit float and runs it; the sample rows. */
    private List<double[]> run(Path script, double tick, long ticks, long every) throws Exception {
        Path dir = tmp.resolve("c-" + script.getFileName());
        Cli export = Cli.run(List.of("export", script.toString(), "--target", "c", "--tick", String.valueOf(tick),
                "--out", dir.toString()));
        assertEquals(0, export.code, () -> "export: " + export);
        Files.copy(REAL32.resolve("long_run.c"), dir.resolve("long_run.c"));
        List<String> cmd = new ArrayList<>(List.of("gcc"));
        cmd.addAll(HostCompiler.C_FLAGS);
        cmd.addAll(List.of("-fsingle-precision-constant", "-include", REAL32.resolve("real32.h").toString(), "-o",
                "long_run", "parsl_rt.c", "parsl_inst.c", "parsl_program.c", "long_run.c", "-lm"));
        HostCompiler.Result cc = HostCompiler.run(dir, cmd, 120);
        assertEquals(0, cc.code(), () -> "gcc failed:\n" + cc.err());
        HostCompiler.Result r = HostCompiler.run(dir, List.of(dir.resolve("long_run").toString(), String.valueOf(ticks),
                String.valueOf(every)), 120);
        assertEquals(0, r.code(), () -> "long_run: " + r.out() + r.err());
        List<double[]> rows = new ArrayList<>();
        for (String line : r.out().lines().toList()) {
            String[] f = line.split(" ");
            double[] row = new double[f.length];
            for (int i = 0; i < f.length; i++) {
                row[i] = Double.parseDouble(f[i]);
            }
            rows.add(row);
        }
        return rows;
    }
}
