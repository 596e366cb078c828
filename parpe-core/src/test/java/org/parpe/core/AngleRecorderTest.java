package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.model.Program;
import org.parpe.core.plot.AngleRecorder;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;

/**
 * The one recorder of every plot (issue 19 item 6: the command line and the IDE each had their
 * own, and "measured" meant the simulator's angle after the tick in one and the reading before
 * it in the other). Measured is the sensor source's angle reading of the same tick.
 */
class AngleRecorderTest {
    private static final String WAVE = RunTimeErrorTest.wave("10 * $time", "");

    private static Run.Builder run(double seconds) {
        Program p = RunTimeErrorTest.load(WAVE);
        return Run.builder(p, RunOptions.defaults(), new DiagnosticList()).duration(seconds);
    }

    /** {@code r} after recording a run of {@code seconds} without a sensor source. */
    private static AngleRecorder recorded(double seconds, AngleRecorder r) throws Exception {
        Run.Builder b = run(seconds);
        r.attachTo(b);
        b.build().execute();
        return r;
    }

    @Test
    void measuredIsTheSensorReadingOfTheTickItIsPlottedAt() throws Exception {
        RunTest.TickPlant plant = new RunTest.TickPlant();
        Run.Builder b = run(0.05);
        b.plant(plant).sensorSource(org.parpe.core.run.SourceKind.SIMULATOR, plant);
        AngleRecorder r = AngleRecorder.latest(64, 0).attachTo(b);
        java.util.List<Double> given = new java.util.ArrayList<>();
        b.observer((tick, time, commanded) -> given.add(commanded[0]));
        b.build().execute();
        double[] t = new double[64];
        double[] cmd = new double[64];
        double[] meas = new double[64];
        int n = r.copy(0, t, cmd, meas);
        assertEquals(6, n, "ticks 0..5");
        for (int k = 0; k < n; k++) {
            assertEquals(k * 0.01, t[k], 1e-9);
            assertEquals(given.get(k), cmd[k], 1e-9, "commanded of tick " + k);
            // The plant reads 100 + the last tick it was given: before tick k it has been given tick k - 1.
            assertEquals(99 + k, meas[k], 1e-9, "measured of tick " + k + " is the reading the scheduler used then");
        }
    }

    @Test
    void withoutASensorSourceNothingIsMeasured() throws Exception {
        AngleRecorder r = recorded(0.03, AngleRecorder.latest(64, 0));
        double[] t = new double[64];
        double[] cmd = new double[64];
        double[] meas = new double[64];
        assertEquals(4, r.copy(1, t, cmd, meas));
        for (int k = 0; k < 4; k++) {
            assertTrue(Double.isNaN(meas[k]), "a commanded angle echoed back is not a measurement");
        }
    }

    @Test
    void aWholeRunKeepsItsBeginningAndEndEvenlySpacedWithinItsCapacity() throws Exception {
        AngleRecorder r = recorded(1.0, AngleRecorder.wholeRun(16));
        double[] t = new double[16];
        int n = r.copy(0, t, new double[16], new double[16]);
        assertTrue(n >= 8 && n <= 16, "between half and all of the capacity, got " + n);
        assertEquals(0, t[0], 1e-9, "the beginning stays");
        assertTrue(t[n - 1] > 1.0 - 2 * (t[1] - t[0]), "the end is kept, got " + t[n - 1]);
        for (int k = 1; k < n; k++) {
            assertEquals(t[1] - t[0], t[k] - t[k - 1], 1e-9, "evenly spaced at sample " + k);
        }
    }

    @Test
    void aWindowKeepsTheNewestSamplesAtItsInterval() throws Exception {
        AngleRecorder r = recorded(1.0, AngleRecorder.latest(10, 0.05));
        double[] t = new double[10];
        assertEquals(10, r.copy(0, t, new double[10], new double[10]));
        assertEquals(1.0, t[9], 1e-9, "the newest sample is the last tick");
        assertEquals(0.55, t[0], 1e-9, "ten samples 0.05 s apart");
        assertEquals(0, r.copy(7, t, new double[10], new double[10]), "an unknown module has no samples");
    }
}
