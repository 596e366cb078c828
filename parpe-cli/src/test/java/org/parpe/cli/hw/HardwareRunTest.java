package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.PtyPair;

/** {@code parpe run --port} against the emulator over a socat pty pair: real bytes end to end. */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class HardwareRunTest {
    static final String SCRIPT = """
            <program>
              <robot><structure><body elements="0..3"/><tail elements="9"/></structure></robot>
              <states><up angles="40"/><down angles="-40"/><far angles="120"/></states>
              <automata><wave states="up, down" times="0.5, 0.5"/></automata>
              <behaviors><snake><wave group="body" phase="0.25"/></snake></behaviors>
              <main><snake/></main>
            </program>
            """;

    @TempDir
    Path dir;

    @BeforeAll
    static void needSocat() {
        assumeTrue(PtyPair.available(), "socat is not installed (./test-all installs it)");
    }

    Path script() throws Exception {
        Path f = dir.resolve("snake.xml");
        Files.writeString(f, SCRIPT);
        return f;
    }

    @Test
    void theModulesReceiveTheTracesAnglesAndMissingOnesAreReportedFirst() throws Exception {
        Path trace = dir.resolve("t.csv");
        try (EmulatedBus bus = new EmulatedBus(dir, EmulatorOptions.of(0, 1, 2, 3))) {
            Cli r = Cli.run("run", script().toString(), "--port", bus.port(), "--duration", "2", "--trace", trace.toString());
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.contains("4 of 5 modules answer (0..3)"), r.err);
            assertTrue(r.err.contains("module 9 of the script does not answer; it moves once it answers"), r.err);
            assertTrue(r.err.indexOf("does not answer") < r.err.indexOf("frames sent"), r.err);
            Traces t = new Traces(trace);
            assertEquals(201, t.rows.size());
            int matched = 0;
            for (Map.Entry<Integer, double[]> e : bus.received.entrySet()) {
                double[] row = t.rows.get(e.getKey());
                for (int m = 0; m < 4; m++) {
                    assertEquals(row[1 + m], e.getValue()[m], 0.005 + 1e-9, "tick " + e.getKey() + " module " + m);
                }
                matched++;
            }
            // Realtime pacing leaves the bus idle most of each tick, so nearly every tick arrives; a
            // loaded machine can delay the bus thread past a tick, and then the newest setpoints win.
            assertTrue(matched >= 120, "only " + matched + " of 201 ticks reached the modules");
            assertTrue(bus.received.containsKey(200), "the last tick reached the modules");
            Thread.sleep(400);
            double[] last = t.rows.get(200);
            for (int m = 0; m < 4; m++) {
                assertEquals(last[1 + m], bus.emulator.angle(m), 0.01, "module " + m + " ends at the last setpoint");
            }
            double hw = t.rows.get(200)[t.column("hw1")];
            assertTrue(Math.abs(hw - t.rows.get(199)[2]) < 15, "hw1 column holds a measured angle: " + hw);
        }
    }

    /** PARSL.md §14: on hardware without latches each plate action is told once per plate, located, never dropped. */
    @Test
    void plateActionsAreToldOncePerPlateOnModulesWithoutLatches() throws Exception {
        Path f = dir.resolve("dock.xml");
        Files.writeString(f, """
                <program>
                  <robot><structure><body elements="0..3"/></structure><actuators><latch elements="0, 3"/></actuators></robot>
                  <states><up angles="40" latch="0"/><down angles="-40" unlatch="0"/></states>
                  <automata><wave states="up, down" times="0.5, 0.5"/></automata>
                  <behaviors><b><wave group="ends"/></b></behaviors>
                  <main><b/></main>
                </program>
                """.replace("<body elements=\"0..3\"/>", "<body elements=\"0..3\"/><ends elements=\"0, 3\"/>"));
        try (EmulatedBus bus = new EmulatedBus(dir, EmulatorOptions.of(0, 1, 2, 3))) {
            Cli r = Cli.run("run", f.toString(), "--port", bus.port(), "--duration", "2.2");
            assertEquals(0, r.code, r.toString());
            String armed = f + ":3:12: warning: at t=0.000 s module 0 arms plate 0, but the modules on " + bus.port()
                    + " have no latching plates: join that plate to the plate it meets by hand";
            assertTrue(r.err.contains(armed), r.err);
            assertTrue(r.err.contains(f + ":3:39: warning: at t=0.500 s module 3 releases plate 0"), r.err);
            // four cycles arm and release each plate four times: each is told once
            assertEquals(4, r.err.split("have no latching plates", -1).length - 1, r.err);
        }
    }

    @Test
    void withDropsAndCorruptionTheRunCompletesAndReportsTheFaults() throws Exception {
        try (EmulatedBus bus = new EmulatedBus(dir, EmulatorOptions.of(0, 1, 2, 3, 9).withFaults(0.05, 0.05, 1))) {
            Cli r = Cli.run("run", script().toString(), "--port", bus.port(), "--duration", "2");
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.matches("(?s).*\\(([1-9]\\d*) timeouts.*"), r.err);
            assertTrue(r.err.matches("(?s).*, ([1-9]\\d*) bad checksums received.*"), r.err);
            assertTrue(r.err.matches("(?s).*modules rejected ([1-9]\\d*) frames.*"), r.err);
            assertTrue(bus.emulator.stats().dropped() > 0);
            assertTrue(bus.received.size() > 50, "setpoints got through: " + bus.received.size());
        }
    }

    /* Safety bound: see BusOverPtyTest in parpe-serial for the budget (50 ms watchdog + margin). */
    @Test
    void anUnpluggedCableStopsTheModulesWithinTheBoundAndTheRunSaysSo() throws Exception {
        try (EmulatedBus bus = new EmulatedBus(dir, EmulatorOptions.of(0, 1, 2, 3, 9).withUnplug(1.0, -1))) {
            Cli r = Cli.run("run", script().toString(), "--port", bus.port(), "--duration", "1.8", "--on-fault", "limp");
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.contains("no reply from any module"), r.err);
            assertTrue(r.err.contains("modules stop on their watchdog (limp)"), r.err);
            assertTrue(bus.unplugNanos != 0);
            long after = bus.stops.stream().filter(s -> s[1] >= bus.unplugNanos).count();
            assertEquals(5, after, "every module stopped after the unplug");
            for (long[] s : bus.stops) {
                if (s[1] >= bus.unplugNanos) {
                    assertTrue((s[1] - bus.unplugNanos) / 1e6 < 100, "module " + s[0] + " stopped after "
                            + (s[1] - bus.unplugNanos) / 1e6 + " ms");
                    assertTrue(bus.emulator.isLimp((int) s[0]));
                }
            }
        }
    }

    @Test
    void outOfRangeAnglesAreClampedNeverSent() throws Exception {
        Path f = dir.resolve("far.xml");
        Files.writeString(f, SCRIPT.replace("states=\"up, down\"", "states=\"far, down\""));
        try (EmulatedBus bus = new EmulatedBus(dir, EmulatorOptions.of(0, 1, 2, 3))) {
            Cli r = Cli.run("run", f.toString(), "--port", bus.port(), "--duration", "1");
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.contains("outside the joint range ±90°; sending 90°"), r.err);
            for (double[] a : bus.received.values()) {
                for (double v : a) {
                    assertTrue(Double.isNaN(v) || Math.abs(v) <= 90, "sent " + v);
                }
            }
        }
    }

    @Test
    void hardwareAndSimulatorRunTogetherAndDivergenceIsReported() throws Exception {
        Path trace = dir.resolve("both.csv");
        try (EmulatedBus bus = new EmulatedBus(dir, EmulatorOptions.of(0, 1, 2, 3, 9))) {
            Cli r = Cli.run("run", script().toString(), "--port", bus.port(), "--sim", "--diverge", "0.0001",
                    "--duration", "1", "--trace", trace.toString());
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.matches("(?s).*diverge: module \\d at t=.*more than 0\\.00° apart.*"), r.err);
            assertTrue(r.err.matches("(?s).*diverge: module \\d was more than 0\\.00° off for .*"), r.err);
            Traces t = new Traces(trace);
            t.column("hw0");
            // When the simulator runs slower than real time, ticks come in bursts and the bus sends
            // the newest of each burst: not every tick, but the hardware follows the run.
            assertTrue(bus.received.size() > 20, "the hardware was driven too: " + bus.received.size());
            assertTrue(bus.received.containsKey(100), "the last tick reached the modules: " + r.err);
            r = Cli.run("run", script().toString(), "--port", bus.port(), "--sim", "--diverge", "1000", "--duration", "0.5");
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.contains("diverge: hardware and simulator stayed within 1000.00°"), r.err);
        }
    }

    @Test
    void badPortsAndOptionsGetAClearMessage() throws Exception {
        Cli r = Cli.run("run", script().toString(), "--port", dir.resolve("nothing").toString());
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("serial device " + dir.resolve("nothing") + " does not exist"), r.err);
        assertTrue(!r.err.contains("Exception"), r.err);
        r = Cli.run("run", script().toString(), "--port", dir.toString());
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("is not a serial device"), r.err);
        r = Cli.run("run", script().toString(), "--diverge", "5");
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("--diverge"), r.err);
        r = Cli.run("run", script().toString(), "--port", "/dev/null", "--on-fault", "explode");
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("--on-fault must be hold or limp"), r.err);
        r = Cli.run("emulate", "--port", dir.resolve("nothing").toString(), "--modules", "0..x");
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("--modules expects module IDs or ranges like 0..7, got '0..x'"), r.err);
        r = Cli.run("emulate", "--port", dir.resolve("nothing").toString(), "--modules", "0..300");
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("module ID must be in 0..254"), r.err);
        r = Cli.run("emulate", "--port", dir.resolve("nothing").toString(), "--drop", "2");
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("drop probability must be in 0..1, got 2.0"), r.err);
    }

    @Test
    void noModuleAnsweringIsAUsageError() throws Exception {
        try (EmulatedBus bus = new EmulatedBus(dir, EmulatorOptions.of(20))) {
            Cli r = Cli.run("run", script().toString(), "--port", bus.port(), "--duration", "1");
            assertEquals(2, r.code, r.toString());
            assertTrue(r.err.contains("no module answers on " + bus.port()), r.err);
        }
    }
}
