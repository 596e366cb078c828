package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.Severity;
import org.parpe.core.model.Program;
import org.parpe.core.run.SourceKind;
import org.parpe.core.sensor.Channel;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.SensorSource;
import org.parpe.core.sensor.SensorTable;
import org.parpe.core.run.TargetException;
import org.parpe.core.run.TraceColumns;
import org.parpe.core.run.WallClockPacer;

/**
 * The one run pipeline of the core: plants before observers whatever the order of
 * registration, the sensor source by priority, duration, cancellation, run-time errors as
 * diagnostics, and resources closed in every case.
 */
class RunTest {
    private static final String WAVE = RunTimeErrorTest.wave("10 * $time", "");

    /** A plant that remembers the last tick it was given and reports it as a trace column and as the angle reading. */
    static final class TickPlant implements JointSink, TraceColumns, SensorSource {
        long accepted = -1;
        boolean closed;

        @Override
        public void accept(long tick, double time, double[] commanded) {
            accepted = tick;
        }

        @Override
        public String[] names() {
            return new String[] {"plant_tick"};
        }

        @Override
        public void values(double[] out) {
            out[0] = accepted;
        }

        @Override
        public void read(double time, SensorTable table) {
            table.set(0, Channel.ANGLE, 100 + accepted);
        }
    }

    private static List<String[]> rows(StringWriter trace) {
        List<String[]> out = new ArrayList<>();
        for (String line : trace.toString().split("\n")) {
            out.add(line.split(","));
        }
        return out;
    }

    @Test
    void observersSeeThePlantsOfTheSameTickWhateverTheOrderOfRegistration() throws Exception {
        Program p = RunTimeErrorTest.load(WAVE);
        TickPlant plant = new TickPlant();
        StringWriter trace = new StringWriter();
        List<Long> seenByObserver = new ArrayList<>();
        Run.Builder b = Run.builder(p, RunOptions.defaults(), new DiagnosticList())
                .trace(trace)
                .observer((tick, time, commanded) -> seenByObserver.add(plant.accepted))
                .duration(0.05);
        // The plant and its columns come after the trace and the observer.
        b.attach(run -> run.plant(plant).traceColumns(plant));
        RunOutcome o = b.build().execute();
        assertEquals(RunOutcome.Status.COMPLETED, o.status());
        List<String[]> rows = rows(trace);
        assertEquals("plant_tick", rows.get(0)[rows.get(0).length - 1]);
        assertEquals(7, rows.size(), "header and ticks 0..5");
        for (int k = 0; k <= 5; k++) {
            String[] row = rows.get(k + 1);
            assertEquals(k + ".000000", row[row.length - 1], "trace row of tick " + k + " shows the plant of another tick");
            assertEquals(k, seenByObserver.get(k));
        }
    }

    @Test
    void theSensorSourceWithTheHighestPriorityIsReadWhateverTheOrderOffered() throws Exception {
        Program p = RunTimeErrorTest.load(WAVE);
        TickPlant hw = new TickPlant();
        SensorSource sim = (time, table) -> table.set(0, Channel.ANGLE, -7);
        List<Double> readings = new ArrayList<>();
        Run.Builder b = Run.builder(p, RunOptions.defaults(), new DiagnosticList()).duration(0.02);
        b.sensorSource(SourceKind.HARDWARE, hw).sensorSource(SourceKind.SIMULATOR, sim).plant(hw);
        b.observeReadings((time, table) -> readings.add(table.get(0, Channel.ANGLE)));
        assertEquals(List.of(SourceKind.HARDWARE, SourceKind.SIMULATOR), b.sensorSourceKinds());
        b.build().execute();
        assertEquals(List.of(99.0, 100.0, 101.0), readings, "the hardware is read, not the simulator");
    }

    @Test
    void aRunTimeErrorBecomesALocatedDiagnosticAndResourcesAreClosed() {
        Program p = RunTimeErrorTest.load(RunTimeErrorTest.wave("10 / ($time - 0.5)", ""));
        DiagnosticList diags = new DiagnosticList();
        TickPlant resource = new TickPlant();
        AtomicReference<RunOutcome> finished = new AtomicReference<>();
        StringWriter trace = new StringWriter();
        RunOutcome o = Run.builder(p, RunOptions.defaults(), diags).trace(trace)
                .closeAtEnd(() -> resource.closed = true).onFinish(finished::set).build().execute();
        assertEquals(RunOutcome.Status.ERROR, o.status());
        assertEquals(o, finished.get());
        assertTrue(resource.closed);
        assertEquals(1, diags.all().size(), diags.all().toString());
        Diagnostic d = diags.all().get(0);
        assertEquals(Severity.ERROR, d.severity());
        assertEquals("rt.xml:8:12", d.pos().toString());
        assertTrue(d.message().startsWith("division by zero in '10 / ($time - 0.5)' (at t=0.500000 s)"), d.message());
        assertEquals(d.format(), o.message());
        assertEquals(51, rows(trace).size(), "completed rows are kept, the failing tick is not written");
    }

    @Test
    void aStopRequestedWhileAssemblingEndsTheRunBeforeItsFirstTick() throws Exception {
        Program p = RunTimeErrorTest.load(WAVE);
        TickPlant plant = new TickPlant();
        Run.Builder b = Run.builder(p, RunOptions.defaults(), new DiagnosticList());
        b.attach(run -> {
            run.plant(plant).closeAtEnd(() -> plant.closed = true);
            run.engine().requestStop(); // e.g. the user pressed Stop during a bus scan
        });
        RunOutcome o = b.build().execute();
        assertEquals(RunOutcome.Status.STOPPED, o.status());
        assertEquals(-1, plant.accepted, "no tick may run after a stop");
        assertTrue(plant.closed);
    }

    @Test
    void aPausedRunStopsWhenAskedFromAnotherThread() throws Exception {
        Program p = RunTimeErrorTest.load(WAVE);
        WallClockPacer pacer = new WallClockPacer(1);
        pacer.setPaused(true);
        Run run = Run.builder(p, RunOptions.defaults(), new DiagnosticList()).pacer(pacer).build();
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        Thread t = new Thread(() -> outcome.set(run.execute()));
        t.start();
        run.requestStop();
        t.join(10_000);
        assertFalse(t.isAlive(), "a paused run did not stop");
        assertEquals(RunOutcome.Status.STOPPED, outcome.get().status());
    }

    @Test
    void aTargetThatCannotBeUsedIsAbandonedWithItsResourcesClosed() {
        Program p = RunTimeErrorTest.load(WAVE);
        TickPlant opened = new TickPlant();
        Run.Builder b = Run.builder(p, RunOptions.defaults(), new DiagnosticList());
        TargetException e = org.junit.jupiter.api.Assertions.assertThrows(TargetException.class, () -> b.attach(run -> {
            run.closeAtEnd(() -> opened.closed = true);
            throw new TargetException(org.parpe.core.diag.SourcePos.origin("bus /dev/ttyX"), "no module answers");
        }));
        b.abandon();
        assertTrue(opened.closed);
        assertEquals("bus /dev/ttyX: error: no module answers", e.diagnostics().get(0).format());
    }

    @Test
    void durationLimitsTheTicksAsRule1Says() {
        Program p = RunTimeErrorTest.load(WAVE);
        StringWriter trace = new StringWriter();
        RunOutcome o = Run.builder(p, new RunOptions(0.1, 0, List.of()), new DiagnosticList()).trace(trace)
                .duration(0.3).build().execute();
        assertEquals(RunOutcome.Status.COMPLETED, o.status());
        List<String[]> rows = rows(trace);
        assertEquals("0.300000", rows.get(rows.size() - 1)[0]);
        assertEquals(5, rows.size());
    }

    @Test
    void startTellsPlantsBeforeObservers() {
        Program p = RunTimeErrorTest.load(WAVE);
        List<String> order = new ArrayList<>();
        Run.builder(p, RunOptions.defaults(), new DiagnosticList()).duration(0)
                .observer(new JointSink() {
                    @Override
                    public void start(RunInfo info) {
                        order.add("observer");
                    }

                    @Override
                    public void accept(long tick, double time, double[] commanded) {
                    }
                })
                .plant(new JointSink() {
                    @Override
                    public void start(RunInfo info) {
                        order.add("plant");
                    }

                    @Override
                    public void accept(long tick, double time, double[] commanded) {
                    }
                }).build().execute();
        assertEquals(List.of("plant", "observer"), order);
    }
}
