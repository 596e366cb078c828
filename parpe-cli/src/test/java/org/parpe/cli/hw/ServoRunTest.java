package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.PtyPair;
import org.parpe.serial.servo.ServoModel;

/** {@code parpe run --hardware} on Dynamixel 2.0 and Feetech servos emulated over a socat pty pair. */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class ServoRunTest {
    static final String PROFILE = """
            <hardware protocol="%s" baud="1000000">
              <servo module="0" id="1"/>
              <servo module="1" id="2" zero="10" direction="-1"/>
              <servo module="2" id="3" min="-30" max="30"/>
              <servo module="3" id="4"/>
            </hardware>
            """;

    @TempDir
    Path dir;

    @BeforeAll
    static void needSocat() {
        assumeTrue(PtyPair.available(), "socat is not installed (./test-all installs it)");
    }

    Path file(String name, String text) throws Exception {
        Path f = dir.resolve(name);
        Files.writeString(f, text);
        return f;
    }

    Cli run(EmulatedServos servos, String protocol, String... more) throws Exception {
        Path script = file("snake.xml", HardwareRunTest.SCRIPT);
        Path profile = file("robot.xml", PROFILE.formatted(protocol));
        String[] args = {"run", script.toString(), "--hardware", profile.toString(), "--port", servos.port()};
        String[] all = java.util.Arrays.copyOf(args, args.length + more.length);
        System.arraycopy(more, 0, all, args.length, more.length);
        return Cli.run(all);
    }

    @Test
    void dynamixelServosFollowTheTraceThroughZeroDirectionAndLimits() throws Exception {
        ServoModel xl430 = ServoModel.named("xl430-w250");
        try (EmulatedServos s = new EmulatedServos(dir, xl430, EmulatorOptions.of(1, 2, 3, 4))) {
            Path trace = dir.resolve("t.csv");
            Cli r = run(s, "dxl2", "--duration", "1.5", "--trace", trace.toString());
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.contains("4 of 4 servos answer (modules 0..3)"), r.err);
            assertTrue(r.err.contains("modules 9 of the script have no <servo> in the profile; they will not move"), r.err);
            assertTrue(r.err.matches("(?s).*: warning: module 2 commanded -?3\\d\\.\\d\\d° at tick \\d+, .*"), r.err);
            assertTrue(r.err.contains("outside its limits -30.00..30.00°"), r.err);
            assertTrue(r.err.contains("servos stop and hold after 60 ms without a packet (Bus Watchdog)"), r.err);
            assertTrue(r.err.matches("(?s).*bus .* \\(dxl2\\): \\d+ packets sent.*"), r.err);
            Traces t = new Traces(trace);
            double[] last = t.rows.get(t.rows.size() - 1);
            double tick = xl430.degreesPerTick();
            Settle.angle(last[1], () -> s.emulator.angle(1), tick, () -> "module 0 = servo 1");
            Settle.angle(10 - last[2], () -> s.emulator.angle(2), tick,
                    () -> "module 1 turns servo 2 the other way around 10°");
            Settle.angle(Math.max(-30, Math.min(30, last[3])), () -> s.emulator.angle(3), tick,
                    () -> "module 2 within its limits");
            double low = Double.MAX_VALUE;
            double high = -Double.MAX_VALUE;
            for (double[] row : t.rows) {
                low = Math.min(low, row[1]);
                high = Math.max(high, row[1]);
            }
            double hw0 = last[t.column("hw0")];
            assertTrue(hw0 >= low - tick && hw0 <= high + tick,
                    "hw0 holds a measured angle within what module 0 was commanded: " + hw0 + " in " + low + ".." + high);
            assertTrue(!s.emulator.isLimp(1), "the servos hold at the end");
            assertTrue(s.goals.size() > 50, "goals received: " + s.goals.size());
            for (double[] g : s.goals) {
                assertTrue(Double.isNaN(g[2]) || Math.abs(g[2]) <= 30 + tick, "servo 3 was sent " + g[2] + "°");
            }
        }
    }

    @Test
    void feetechServosRunToo() throws Exception {
        ServoModel sts = ServoModel.named("sts3215");
        try (EmulatedServos s = new EmulatedServos(dir, sts, EmulatorOptions.of(1, 2, 3, 4))) {
            Cli r = run(s, "sts", "--duration", "1");
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.contains("4 of 4 servos answer"), r.err);
            assertTrue(r.err.contains("Feetech servos have no watchdog"), r.err);
            Settle.until(() -> Math.abs(s.emulator.angle(1)) > 1, () -> "servo 1 moved: " + s.emulator.angle(1));
        }
    }

    @Test
    void aServoFaultIsReportedInWordsNotAsAStackTrace() throws Exception {
        try (EmulatedServos s = new EmulatedServos(dir, ServoModel.named("xm430-w210"), EmulatorOptions.of(1, 2, 3, 4))) {
            Thread faulter = new Thread(() -> {
                try {
                    // After set-up: a servo faulty at the start stays limp, which stops the run.
                    while (s.emulator.isLimp(1) || s.emulator.isLimp(4)) {
                        Thread.sleep(5);
                    }
                    Thread.sleep(300);
                    s.emulator.fault(3, 0x20);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            });
            faulter.start();
            Cli r = run(s, "dxl2", "--duration", "1.2");
            faulter.join();
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.contains("servo 3 (module 2) reports overload; it may have turned its torque off"), r.err);
            assertTrue(r.err.contains("1 servo faults"), r.err);
            assertTrue(!r.err.contains("Exception"), r.err);
        }
    }

    @Test
    void pulledCableIsReportedAndTheRunEnds() throws Exception {
        try (EmulatedServos s = new EmulatedServos(dir, ServoModel.named("xl330-m288"),
                EmulatorOptions.of(1, 2, 3, 4).withUnplug(1.5, -1))) {
            // The cable comes out well after discovery, even on a loaded machine.
            Cli r = run(s, "dxl2", "--duration", "2.5");
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.contains("no reply from any servo"), r.err);
            assertTrue(r.err.contains("servos hold their last goal"), r.err);
            assertTrue(r.err.matches("(?s).* [1-9]\\d* disconnects.*"), r.err);
            assertTrue(r.err.indexOf("no reply from any servo") > r.err.indexOf("servos answer"), r.err);
        }
    }

    @Test
    void profileErrorsAreLocatedAndNothingIsOpened() throws Exception {
        Path script = file("snake.xml", HardwareRunTest.SCRIPT);
        Path profile = file("bad.xml", "<hardware protocol=\"dxl2\">\n  <servo module=\"0\" id=\"1\" model=\"ax-12\"/>\n"
                + "  <servo module=\"1\"/>\n</hardware>\n");
        Cli r = Cli.run("run", script.toString(), "--hardware", profile.toString(), "--port", "/nonexistent");
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains(profile + ":2:3: error: unknown dxl2 servo model 'ax-12'"), r.err);
        assertTrue(r.err.contains(profile + ":3:3: error: <servo> needs the attribute 'id'"), r.err);
    }

    @Test
    void g1ModulesRunThroughAProfileToo() throws Exception {
        try (EmulatedBus bus = new EmulatedBus(dir, EmulatorOptions.of(0, 1, 2, 3))) {
            Path script = file("snake.xml", HardwareRunTest.SCRIPT);
            Path profile = file("g1.xml", """
                    <hardware protocol="g1">
                      <servo module="0" id="0" zero="5" max="85"/>
                      <servo module="1" id="1"/>
                      <servo module="2" id="2"/>
                      <servo module="3" id="3" direction="-1"/>
                    </hardware>
                    """);
            Path trace = dir.resolve("g1.csv");
            Cli r = Cli.run("run", script.toString(), "--hardware", profile.toString(), "--port", bus.port(),
                    "--duration", "1", "--trace", trace.toString());
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.contains("(g1, 115200 baud): 4 of 4 servos answer"), r.err);
            assertTrue(r.err.contains("modules hold after 60 ms without a frame (module watchdog)"), r.err);
            Traces t = new Traces(trace);
            double[] last = t.rows.get(t.rows.size() - 1);
            Settle.angle(5 + last[1], () -> bus.emulator.angle(0), 0.01, () -> "module 0 through zero 5");
            Settle.angle(-last[4], () -> bus.emulator.angle(3), 0.01, () -> "module 3 turned the other way");
        }
    }

    @Test
    void theEmulateCommandServesDynamixelServosThatScanFinds() throws Exception {
        try (PtyPair pty = PtyPair.start(dir.resolve("ea"), dir.resolve("eb"))) {
            java.util.concurrent.CompletableFuture<Cli> emu = java.util.concurrent.CompletableFuture.supplyAsync(() ->
                    Cli.run("emulate", "--protocol", "dxl2", "--model", "xm430-w210", "--port", pty.b().toString(),
                            "--modules", "1..2", "--duration", "3"));
            Thread.sleep(800);
            Cli scan = Cli.run("scan", "--port", pty.a().toString(), "--protocol", "dxl2", "--baud", "1000000",
                    "--ids", "0..4", "--out", dir.resolve("e.xml").toString());
            assertEquals(0, scan.code, scan.toString());
            assertTrue(scan.out.contains("2 dxl2 servos"), scan.out);
            assertTrue(scan.out.contains("xm430-w210 (1030)"), scan.out);
            Cli e = emu.get(20, TimeUnit.SECONDS);
            assertEquals(0, e.code, e.toString());
            assertTrue(e.err.contains("emulate: 2 dxl2 servos xm430-w210 (1030) (1, 2)"), e.err);
            assertTrue(e.err.matches("(?s).*emulate: [1-9]\\d* packets accepted.*"), e.err);
        }
    }

    @Test
    void aServoOfAnotherControlTableThanTheProfileSaysDoesNotMove() throws Exception {
        try (EmulatedServos s = new EmulatedServos(dir, ServoModel.named("xl-320"), EmulatorOptions.of(1, 2, 3, 4))) {
            Cli r = run(s, "dxl2", "--duration", "0.5");
            assertEquals(2, r.code, r.toString());
            assertTrue(r.err.contains("servo 1 (module 0) is an xl-320 (350), the profile says xl430-w250 (1060) at "),
                    r.err);
            assertTrue(r.err.contains("it will not move (correct the model in the profile)"), r.err);
            // They answer, so "is the robot powered?" would send the user the wrong way.
            assertTrue(r.err.contains("error: the servos on " + s.port() + " answer, but not as the model the profile "
                    + "says (modules 0..3"), r.err);
            assertTrue(r.err.contains("0 of 4 servos answer; 4 more answer as another model"), r.err);
        }
    }

    @Test
    void emulateRefusesAModelOfAnotherProtocol() {
        Cli r = Cli.run("emulate", "--protocol", "sts", "--model", "xl430-w250", "--port", "/nonexistent");
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("--model 'xl430-w250' is not a sts servo PARPE knows; known: sts3215"), r.err);
    }
}
