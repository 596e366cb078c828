package org.parpe.serial.servo.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.BusReport;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.g1.emu.BusEmulator;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.link.PipeLink;
import org.parpe.serial.link.WatchedLink;
import org.parpe.serial.g1.Protocol;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.emu.ServoEmulator;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ServoMapping;

/**
 * What {@code --port}'s driver did for G1 modules before it was folded into {@link ServoDriver},
 * now the one driver's: a module missing at discovery is driven once it answers, a module that
 * stops answering is read less often, and the modules' accelerometers and touch sensors reach
 * the run; a Dynamixel servo missing at discovery is driven once it answers too. Between host and emulator, a gate swallows every frame addressed to the modules it
 * holds, as if their cable were out (the emulator has no way to silence one module). Each test
 * failed before the fold: ServoDriver never looked for a missing servo again, read a silent one
 * every round, and handed the run angles only.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class ModulesComeAndGoTest {
    static final int[] MODULES = {0, 1, 2, 3, 4};

    final Set<Integer> gated = ConcurrentHashMap.newKeySet();
    final List<String> reports = new CopyOnWriteArrayList<>();
    BusEmulator emulator;
    ServoEmulator servos;
    ServoDriver driver;

    void open() throws IOException {
        PipeLink[] pipe = PipeLink.pair("gate");
        emulator = BusEmulator.start(() -> pipe[1], EmulatorOptions.of(MODULES), new EmulatorListener() { });
        BusConfig config = BusConfig.defaults();
        // Byte 2 of a G1 frame is its address (docs/hardware-protocol.md, frame layout).
        driver = ServoDriver.open(() -> gate(pipe[0], 2), config, HardwareProfile.ofModules("gate", config, MODULES),
                MODULES, BusReport.lines(reports::add));
    }

    @AfterEach
    void close() {
        if (driver != null) {
            driver.close();
        }
        if (emulator != null) {
            emulator.close();
        }
        if (servos != null) {
            servos.close();
        }
    }

    /** Feeds setpoints of {@code deg} every 5 ms until {@code done} holds (at most 10 s). */
    void driveUntil(double deg, BooleanSupplier done, String what) throws InterruptedException {
        double[] row = new double[MODULES.length];
        java.util.Arrays.fill(row, deg);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        for (long k = 0; !done.getAsBoolean(); k++) {
            assertTrue(System.nanoTime() < deadline, what + ": " + reports);
            driver.accept(k, k * 0.005, row);
            Thread.sleep(5);
        }
    }

    @Test
    void aModuleMissingAtDiscoveryIsDrivenOnceItAnswers() throws Exception {
        open();
        gated.add(3);
        assertEquals(List.of(0, 1, 2, 4), driver.discover());
        driver.start(new RunInfo(null, MODULES, 0.01));
        driveUntil(20, () -> Math.abs(emulator.angle(1) - 20) < 0.01, "the others follow");
        assertEquals(0, emulator.angle(3), 1e-9, "a module not driven gets no setpoint");
        gated.clear();
        driveUntil(20, () -> Math.abs(emulator.angle(3) - 20) < 0.01, "module 3 follows once it answers");
        assertTrue(reports.contains("bus: module 3 answers now; driving it"), reports.toString());
        driver.finish(new RunOutcome(RunOutcome.Status.COMPLETED, 1, ""));
    }

    @Test
    void aModuleThatStopsAnsweringIsReadLessOftenAndCounted() throws Exception {
        open();
        assertEquals(List.of(0, 1, 2, 3, 4), driver.discover());
        driver.start(new RunInfo(null, MODULES, 0.01));
        driveUntil(10, () -> Math.abs(driver.measuredAngle(4) - 10) < 0.01, "every module read");
        gated.add(2);
        String given = "bus: module 2 did not answer 3 reads; reading it less often";
        driveUntil(-10, () -> reports.contains(given), "module 2 read less often");
        // The others are still read while module 2 is skipped.
        driveUntil(-10, () -> Math.abs(driver.measuredAngle(4) + 10) < 0.01, "module 4 still read");
        gated.clear();
        driveUntil(-10, () -> Math.abs(driver.measuredAngle(2) + 10) < 0.01, "module 2 read again");
        driver.finish(new RunOutcome(RunOutcome.Status.COMPLETED, 1, ""));
        assertEquals(1, reports.stream().filter(given::equals).count(), "said once per give-up: " + reports);
        String summary = reports.get(reports.size() - 1);
        assertTrue(summary.matches(".*, [1-9]\\d* failed\\).*"), summary);
    }

    @Test
    void accelerometerAndTouchReachTheRun() throws Exception {
        open();
        driver.discover();
        driver.start(new RunInfo(null, MODULES, 0.01));
        emulator.setTouch(1, Protocol.Touch.RIGHT.bit());
        SensorTable table = new SensorTable(MODULES);
        driveUntil(30, () -> {
            driver.read(0, table);
            return Math.abs(table.get(1, Channel.ANGLE) - 30) < 0.01 && table.get(1, Channel.TOUCH_RIGHT) == 1;
        }, "module 1 read at 30° touching on the right");
        // The emulated body turns with its joint: gravity along x is 100·sin(angle), along y −100·cos(angle).
        driveUntil(30, () -> {
            driver.read(0, table);
            return table.get(1, Channel.ACCEL_X) == 50 && table.get(1, Channel.ACCEL_Y) == -87;
        }, "module 1's accelerometer read: " + table.get(1, Channel.ACCEL_X) + ", " + table.get(1, Channel.ACCEL_Y));
        assertEquals(0, table.get(1, Channel.TOUCH_LEFT), 1e-9);
        driver.finish(new RunOutcome(RunOutcome.Status.COMPLETED, 1, ""));
    }

    @Test
    void aDynamixelServoMissingAtDiscoveryIsDrivenOnceItAnswers() throws Exception {
        PipeLink[] pipe = PipeLink.pair("gate");
        ServoModel xl430 = ServoModel.named("xl430-w250");
        servos = ServoEmulator.start(() -> pipe[1], xl430, EmulatorOptions.of(11, 12), new EmulatorListener() { });
        HardwareProfile profile = new HardwareProfile("test", ServoProtocol.DXL2, "gate", 1_000_000, SafeMode.HOLD,
                HardwareProfile.DEFAULT_WATCHDOG_MS, List.of(
                        new ServoMapping(0, 11, xl430, 0, 1, -90, 90, SourcePos.NONE),
                        new ServoMapping(1, 12, xl430, 0, 1, -90, 90, SourcePos.NONE)));
        // Byte 4 of a Dynamixel 2.0 packet is its ID (e-Manual, Protocol 2.0, Instruction Packet:
        // header FF FF FD, reserved 00, then the packet ID).
        driver = ServoDriver.open(() -> gate(pipe[0], 4), BusConfig.defaults().withBaud(1_000_000), profile,
                new int[] {0, 1}, BusReport.lines(reports::add));
        gated.add(12);
        assertEquals(List.of(0), driver.discover());
        driver.start(new RunInfo(null, new int[] {0, 1}, 0.01));
        driveUntil(20, () -> Math.abs(servos.angle(11) - 20) < 0.2, "servo 11 follows");
        double before = servos.angle(12);
        gated.clear();
        driveUntil(20, () -> Math.abs(servos.angle(12) - 20) < 0.2, "servo 12 follows once it answers (from "
                + before + "°)");
        assertTrue(reports.contains("bus: servo 12 (module 1) answers now; driving it"), reports.toString());
        driver.finish(new RunOutcome(RunOutcome.Status.COMPLETED, 1, ""));
    }

    /**
     * The host's end of the line, swallowing every packet addressed to a gated device; the
     * protocol holds the address at {@code addressAt}.
     */
    ByteLink gate(ByteLink link, int addressAt) {
        return new WatchedLink(link, (b, off, len) -> len <= addressAt || !gated.contains(b[off + addressAt] & 0xFF));
    }
}
