package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.PtyPair;
import org.parpe.serial.servo.ServoModel;

/**
 * How {@code calibrate} and {@code scan} write a hardware profile (issue 18, items 1, 3 and 7):
 * an empty reachable range is refused before anything is written, the file keeps its comments,
 * link and mode, {@code --port} stays out of it, and {@code --force} never replaces anything but
 * a regular file. Each of these failed before the output policy.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class ProfileOutputTest {
    @TempDir
    Path dir;

    @BeforeAll
    static void needSocat() {
        assumeTrue(PtyPair.available(), "socat is not installed (./test-all installs it)");
    }

    /** Runs calibrate with servo 1 posed at {@code posed}°; returns the exit code and the log. */
    private static String[] calibrate(EmulatedServos s, double posed, String... args) throws Exception {
        CalibrateSession calibrate = new CalibrateSession(s, new int[] {1}, args);
        assertTrue(s.emulator.backDrive(1, posed));
        int code = calibrate.enter();
        return new String[] {Integer.toString(code), calibrate.log()};
    }

    @Test
    void calibrateRefusesAnEmptyReachableRangeAndLeavesTheFileAsItWas() throws Exception {
        try (EmulatedServos s = new EmulatedServos(dir, ServoModel.named("xm430-w210"), EmulatorOptions.of(1))) {
            Path profile = dir.resolve("robot.xml");
            String text = """
                    <!-- my robot: module 0 is the left hip -->
                    <hardware protocol="dxl2" port="%s" baud="1000000">
                      <servo module="0" id="1" model="xm430-w210" zero="3" min="10" max="80"/>
                    </hardware>
                    """.formatted(s.port());
            Files.writeString(profile, text);
            String[] r = calibrate(s, 174.99, "--hardware", profile.toString());
            assertEquals("1", r[0], r[1]);
            assertTrue(r[1].contains("module 0 cannot reach 10..80° with zero 174.99°: pose it again"), r[1]);
            assertEquals(text, Files.readString(profile));
        }
    }

    @Test
    void calibrateWritesThroughALinkKeepsTheModeAndNotTheTemporaryPort() throws Exception {
        try (EmulatedServos s = new EmulatedServos(dir, ServoModel.named("xm430-w210"), EmulatorOptions.of(1))) {
            Path real = dir.resolve("real.xml");
            Files.writeString(real, """
                    <hardware protocol="dxl2" port="/dev/ttyUSB7" baud="1000000">
                      <servo module="0" id="1" model="xm430-w210"/>
                    </hardware>
                    """);
            Files.setPosixFilePermissions(real, PosixFilePermissions.fromString("rw-rw-r--"));
            Path link = Files.createSymbolicLink(dir.resolve("robot.xml"), real);
            String[] r = calibrate(s, 12.5, "--hardware", link.toString(), "--port", s.port());
            assertEquals("0", r[0], r[1]);
            assertTrue(Files.isSymbolicLink(link), "the link is kept");
            String written = Files.readString(real);
            assertTrue(written.matches("(?s).*zero=\"12\\.[45]\\d?\".*"), written);
            assertTrue(written.contains("port=\"/dev/ttyUSB7\""), "the profile keeps its own port: " + written);
            assertEquals("rw-rw-r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(real)));
        }
    }

    @Test
    void scanForceNeverReplacesADeviceAFifoOrALinkToNothing() throws Exception {
        Path fifo = dir.resolve("fifo.xml");
        new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor();
        Path dangling = Files.createSymbolicLink(dir.resolve("dangling.xml"), dir.resolve("nowhere.xml"));
        for (Path target : List.of(Path.of("/dev/null"), fifo, dangling)) {
            Cli r = Cli.run("scan", "--port", dir.resolve("no-such-port").toString(), "--protocol", "dxl2", "--force",
                    "--out", target.toString());
            assertEquals(2, r.code, r.toString());
            assertTrue(r.err.contains("cannot write --out file '" + target + "'"), r.err);
        }
        assertTrue(Files.isSymbolicLink(dangling));
        assertTrue(!Files.isRegularFile(fifo));
    }

    @Test
    void scanForceWritesThroughALinkAndKeepsTheMode() throws Exception {
        try (EmulatedServos s = new EmulatedServos(dir, ServoModel.named("xl330-m288"), EmulatorOptions.of(3))) {
            Path real = Files.writeString(dir.resolve("real.xml"), "<!-- old -->\n");
            Files.setPosixFilePermissions(real, PosixFilePermissions.fromString("rw-r--r--"));
            Path link = Files.createSymbolicLink(dir.resolve("hw.xml"), real);
            Cli r = Cli.run("scan", "--port", s.port(), "--protocol", "dxl2", "--ids", "0..5", "--force",
                    "--out", link.toString());
            assertEquals(0, r.code, r.toString());
            assertTrue(Files.isSymbolicLink(link));
            assertTrue(Files.readString(real).contains("<servo module=\"0\" id=\"3\""), Files.readString(real));
            assertEquals("rw-r--r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(real)));
        }
    }
}
