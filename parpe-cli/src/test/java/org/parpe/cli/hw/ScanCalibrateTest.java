package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;
import org.parpe.core.diag.Diagnostic;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.PtyPair;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ProfileReader;

/** {@code parpe scan} and {@code parpe calibrate} against emulated servos over a socat pty pair. */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class ScanCalibrateTest {
    @TempDir
    Path dir;

    @BeforeAll
    static void needSocat() {
        assumeTrue(PtyPair.available(), "socat is not installed (./test-all installs it)");
    }

    HardwareProfile read(Path f) {
        List<Diagnostic> d = new ArrayList<>();
        HardwareProfile p = ProfileReader.read(f, d::add);
        assertNotNull(p, d.toString());
        return p;
    }

    @Test
    void scanFindsDynamixelServosAndWritesAStarterProfile() throws Exception {
        ServoModel xl = ServoModel.named("xl330-m288");
        try (EmulatedServos s = new EmulatedServos(dir, xl, EmulatorOptions.of(3, 7, 12))) {
            s.emulator.backDrive(7, 45);
            Path out = dir.resolve("found.xml");
            Cli r = Cli.run("scan", "--port", s.port(), "--protocol", "dxl2", "--ids", "0..20", "--out", out.toString());
            assertEquals(0, r.code, r.toString());
            assertTrue(r.out.contains("3 dxl2 servos on " + s.port() + " at 57600 baud:"), r.out);
            assertTrue(r.out.matches("(?s).*\\n\\s+7  xl330-m288 \\(1200\\)\\s+4[45]\\.\\d\\d°.*"), r.out);
            HardwareProfile p = read(out);
            assertEquals(3, p.servos().size());
            assertEquals(12, p.forModule(2).servo());
            assertEquals("xl330-m288", p.forModule(0).model().name());
            assertEquals(57_600, p.baud());
            Cli again = Cli.run("scan", "--port", s.port(), "--protocol", "dxl2", "--ids", "0..20", "--out", out.toString());
            assertEquals(2, again.code, "an existing profile is kept: " + again);
        }
    }

    @Test
    void scanWithoutProtocolTriesThemAllAndFindsFeetech() throws Exception {
        try (EmulatedServos s = new EmulatedServos(dir, ServoModel.named("sts3215"), EmulatorOptions.of(1, 2))) {
            Path out = dir.resolve("sts.xml");
            Cli r = Cli.run("scan", "--port", s.port(), "--ids", "0..4", "--baud", "1000000", "--out", out.toString());
            assertEquals(0, r.code, r.toString());
            assertTrue(r.err.contains("scan: dxl2 at 1000000 baud"), r.err);
            assertTrue(r.out.contains("2 sts servos"), r.out);
            assertEquals("sts3215", read(out).forModule(1).model().name());
        }
    }

    @Test
    void scanOfAnEmptyBusSaysSo() throws Exception {
        try (PtyPair pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"))) {
            Cli r = Cli.run("scan", "--port", pty.a().toString(), "--protocol", "sts", "--baud", "1000000",
                    "--ids", "0..3", "--out", dir.resolve("x.xml").toString());
            assertEquals(1, r.code, r.toString());
            assertTrue(r.err.contains("no usable servos found on"), r.err);
            assertTrue(r.err.contains("no servo answers"), r.err);
            assertTrue(!Files.exists(dir.resolve("x.xml")));
        }
    }

    @Test
    void scanOfServosOfUnknownModelsWritesNoProfileAndFails() throws Exception {
        // Before, a bus of only unknown models wrote an empty profile "modules 0..-1" and exited 0.
        ServoModel unknown = new ServoModel(org.parpe.serial.servo.ServoProtocol.DXL2, 4242, "mystery", 4096, 360,
                2048, 0, 4095, -1, org.parpe.serial.servo.Registers.DXL_X, -1);
        try (EmulatedServos s = new EmulatedServos(dir, unknown, EmulatorOptions.of(1, 2))) {
            Path out = dir.resolve("none.xml");
            Cli r = Cli.run("scan", "--port", s.port(), "--protocol", "dxl2", "--baud", "57600", "--ids", "0..4",
                    "--out", out.toString());
            assertEquals(1, r.code, r.toString());
            assertTrue(r.out.contains("unknown (4242)"), r.out);
            assertTrue(r.err.contains("scan: no usable servos found on " + s.port()), r.err);
            assertTrue(!Files.exists(out), "no empty profile written");
        }
    }

    @Test
    void dynamixelId253IsRefused() throws Exception {
        // e-Manual, Protocol 2.0, Packet ID: 0 ~ 252; 253 (0xFD) is not used.
        Cli r = Cli.run("scan", "--port", dir.resolve("none").toString(), "--protocol", "dxl2", "--ids", "250..253",
                "--out", dir.resolve("x.xml").toString());
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("--ids: dxl2 servo IDs are 0..252, got 253"), r.err);
    }

    @Test
    void calibrateWritesThePosedAnglesAsZeroOffsets() throws Exception {
        ServoModel xm = ServoModel.named("xm430-w210");
        Path profile = dir.resolve("robot.xml");
        try (EmulatedServos s = new EmulatedServos(dir, xm, EmulatorOptions.of(1, 2))) {
            Files.writeString(profile, """
                    <hardware protocol="dxl2" port="%s" baud="1000000">
                      <servo module="0" id="1" model="xm430-w210"/>
                      <servo module="1" id="2" model="xm430-w210" direction="-1" min="-90" max="90"/>
                    </hardware>
                    """.formatted(s.port()));
            CalibrateSession calibrate = new CalibrateSession(s, new int[] {1, 2}, "--hardware", profile.toString());
            assertTrue(s.emulator.backDrive(1, 12.3));
            assertTrue(s.emulator.backDrive(2, -100));
            assertEquals(0, calibrate.enter(), calibrate.log());
            String log = calibrate.log();
            assertTrue(log.contains("pose the robot with every joint at 0°"), log);
            assertTrue(log.contains("limits narrowed to"), log);
            HardwareProfile p = read(profile);
            assertEquals(12.3, p.forModule(0).zero(), 0.1);
            assertEquals(-100, p.forModule(1).zero(), 0.1);
            // Servo angle -100 + (-1)·joint stays within -180° only for joints up to 80°.
            assertEquals(80, p.forModule(1).max(), 0.1);
            assertEquals(-90, p.forModule(1).min(), 0.1);
            assertTrue(!s.emulator.isLimp(1), "the servos hold after calibration");
            assertEquals(12.3, s.emulator.angle(1), 0.1, "and stay where they were posed");
        }
    }
}
