package org.parpe.serial.servo.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.text.Lang;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.BusReport;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.OverPty;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.emu.ServoEmulator;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ServoMapping;

/** The run driver of profile servos against emulated Dynamixel servos over a socat pty: emergency stop and a vanished device. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class ServoDriverTest extends OverPty {
    static final int[] MODULES = {0, 1, 2};
    static final ServoModel XL430 = ServoModel.named("xl430-w250");

    ServoEmulator emulator;
    ServoDriver driver;
    final List<String> reports = new CopyOnWriteArrayList<>();

    @BeforeEach
    void startEmulator() throws Exception {
        emulator = ServoEmulator.start(LinkOpener.serial(pty.b().toString(), 1_000_000), XL430,
                EmulatorOptions.of(11, 12, 13), new EmulatorListener() { });
        // The first packets of a fresh emulator load its classes, which on a loaded machine takes
        // longer than discovery's retries: wait until it answers before the driver looks.
        try (org.parpe.serial.servo.ServoBus warm = org.parpe.serial.servo.host.ServoBuses.open(ServoProtocol.DXL2,
                LinkOpener.serial(pty.a().toString(), 1_000_000), BusConfig.defaults().withBaud(1_000_000))) {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
            while (warm.ping(13, 1) < 0) {
                assertTrue(System.nanoTime() < deadline, "the emulator did not answer in 5 s");
            }
        }
    }

    @Override
    protected AutoCloseable[] openEnds() {
        return new AutoCloseable[] {driver, emulator};
    }

    void start(SafeMode onFault) throws Exception {
        open(onFault, 90);
        assertEquals(List.of(0, 1, 2), driver.discover());
        driver.start(new RunInfo(null, MODULES, 0.01));
    }

    void open(SafeMode onFault, double limit) throws Exception {
        open(onFault, limit, HardwareProfile.DEFAULT_WATCHDOG_MS);
    }

    void open(SafeMode onFault, double limit, int watchdogMs) throws Exception {
        List<ServoMapping> servos = new ArrayList<>();
        for (int m : MODULES) {
            servos.add(new ServoMapping(m, 11 + m, XL430, 0, 1, -limit, limit, SourcePos.NONE));
        }
        HardwareProfile profile = new HardwareProfile("test", ServoProtocol.DXL2, pty.a().toString(), 1_000_000,
                onFault, watchdogMs, servos);
        driver = ServoDriver.open(LinkOpener.serial(pty.a().toString(), 1_000_000),
                BusConfig.defaults().withBaud(1_000_000), profile, MODULES, BusReport.lines(reports::add));
    }

    @Test
    void aServoWhoseTorqueDoesNotComeOnIsReportedLimp() throws Exception {
        // An X-series servo with a Hardware Error Status bit set refuses Torque Enable = 1 (e-Manual,
        // XL430-W250 control table, Hardware Error Status 70: "Torque Enable is cleared"). Before, the
        // driver sent torque on without reading it back and the run drove a limp servo.
        emulator.fault(12, 0x04);
        open(SafeMode.HOLD, 90);
        assertEquals(List.of(0, 1, 2), driver.discover());
        assertEquals(List.of(1), driver.limp());
        assertTrue(reports.stream().anyMatch(r -> r.startsWith("bus: servo 12 (module 1) did not turn its torque on")),
                reports.toString());
        assertFalse(emulator.isLimp(11) || emulator.isLimp(13), "the others hold");
    }

    @Test
    void theWatchdogIsArmedWhenTrafficStartsNotAtDiscovery() throws Exception {
        // Between discovery and the run's start the program sets up (world, other targets); the Bus
        // Watchdog armed at discovery tripped on every servo then. Failed before. A 300 ms watchdog
        // and a 1 s pause: the run's own traffic keeps far closer than 300 ms even on a loaded machine.
        open(SafeMode.HOLD, 90, 300);
        assertEquals(List.of(0, 1, 2), driver.discover());
        Thread.sleep(1000);
        driver.start(new RunInfo(null, MODULES, 0.01));
        driver.accept(0, 0, new double[] {20, 20, 20});
        await(() -> Math.abs(emulator.angle(13) - 20) < 0.1, "servo 13 at 20°");
        for (int id = 11; id <= 13; id++) {
            assertFalse(emulator.watchdogTripped(id), "servo " + id + " tripped its watchdog");
        }
        driver.finish(new RunOutcome(RunOutcome.Status.COMPLETED, 0, ""));
        assertFalse(reports.stream().anyMatch(r -> r.contains("had stopped on its watchdog")), reports.toString());
    }

    @Test
    void theStartHoldIsClampedIntoTheLimits() throws Exception {
        // A servo resting at 50° with limits ±30°: the hold at start used to be its present
        // position, outside the limits; now it is the limit, rounded inwards.
        assertTrue(emulator.backDrive(12, 50));
        open(SafeMode.HOLD, 30);
        assertEquals(List.of(0, 1, 2), driver.discover());
        // The tick just inside 30°: 4096 ticks a turn (e-Manual, XL430-W250 control table,
        // Goal Position(116), 0.088°/unit), 30° is tick 341.33, so 341 = 29.970703125°. Waiting
        // only for "within 0.1° of 30" caught the servo on its way down from 50° (30.0005°) when
        // the machine was loaded; it must come to rest on the inner tick.
        double inner = 341 * 360.0 / 4096;
        await(() -> emulator.angle(12) == inner, "servo 12 at rest on the tick inside its 30° limit ("
                + inner + "°)");
        assertTrue(emulator.angle(12) <= 30, "never beyond it: " + emulator.angle(12));
        assertFalse(emulator.isLimp(12));
    }

    static void await(BooleanSupplier c, String what) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (!c.getAsBoolean()) {
            assertTrue(System.nanoTime() < deadline, what + " within 5 s");
            Thread.sleep(2);
        }
    }

    @Test
    void emergencyStopWithLimpTurnsTheTorqueOff() throws Exception {
        start(SafeMode.LIMP);
        driver.accept(0, 0, new double[] {60, 60, 60});
        await(() -> emulator.angle(13) > 10, "servo 13 moving");
        driver.emergencyStop();
        await(() -> emulator.isLimp(11) && emulator.isLimp(12) && emulator.isLimp(13), "every servo limp");
        assertTrue(reports.contains("bus: emergency stop sent; servos limp (torque off)"), reports.toString());
        driver.finish(new RunOutcome(RunOutcome.Status.STOPPED, 0, ""));
    }

    @Test
    void emergencyStopWithHoldStopsTheServosWhereTheyAre() throws Exception {
        start(SafeMode.HOLD);
        driver.accept(0, 0, new double[] {80, 80, 80});
        await(() -> emulator.angle(12) > 15, "servo 12 moving");
        driver.emergencyStop();
        double at = emulator.angle(12);
        Thread.sleep(300);
        assertTrue(emulator.angle(12) < 70, "servo 12 stopped near " + at + "°, not at its goal: " + emulator.angle(12));
        assertFalse(emulator.isLimp(12), "and holds with torque on");
        driver.finish(new RunOutcome(RunOutcome.Status.STOPPED, 0, ""));
    }

    @Test
    void aVanishedDeviceIsReportedAndTheRunResumesWhenItIsBack() throws Exception {
        start(SafeMode.HOLD);
        driver.accept(0, 0, new double[] {10, 20, 30});
        await(() -> Math.abs(emulator.angle(13) - 30) < 0.1, "servo 13 at 30°");
        pty.unplug();
        await(() -> reports.stream().anyMatch(r -> r.contains("waiting for the device to return")), "the report");
        pty.restart();
        await(() -> reports.stream().anyMatch(r -> r.startsWith("bus: servos back on")), "the servos back");
        driver.accept(1, 0.01, new double[] {-10, -20, -30});
        await(() -> Math.abs(emulator.angle(13) + 30) < 0.1, "servo 13 following again");
        driver.finish(new RunOutcome(RunOutcome.Status.COMPLETED, 0, ""));
        assertTrue(reports.get(reports.size() - 1).contains("1 disconnects"), reports.toString());
    }

    @Test
    void anEmergencyStopIntoASilentBusIsNotReportedAsDone() throws Exception {
        // A robot silent for a minute used to get "emergency stop sent" as if it had stopped.
        start(SafeMode.HOLD);
        driver.accept(0, 0, new double[] {10, 10, 10});
        await(() -> Math.abs(emulator.angle(13) - 10) < 0.1, "servo 13 at 10°");
        assertTrue(driver.notAnsweringSince() < 0, "answering");
        emulator.close();
        await(() -> reports.stream().anyMatch(r -> r.contains("robot not responding since")), "the silence reported");
        assertTrue(driver.notAnsweringSince() > 0);
        driver.emergencyStop();
        assertTrue(reports.stream().anyMatch(r -> r.startsWith("bus: emergency stop sent but not confirmed: no servo "
                + "has answered since ")), reports.toString());
        assertFalse(reports.contains("bus: emergency stop sent; servos hold where they are"), reports.toString());
    }

    /**
     * A lost robot and the emergency stop into it are told in the user's language (issue 38: the
     * servo buses' messages come from the bundles); before, they were English whatever the language.
     */
    @Test
    void aSilentBusAndItsEmergencyStopAreToldInGerman() throws Exception {
        Lang.use(Locale.GERMAN);
        try {
            start(SafeMode.HOLD);
            driver.accept(0, 0, new double[] {10, 10, 10});
            await(() -> Math.abs(emulator.angle(13) - 10) < 0.1, "servo 13 at 10°");
            emulator.close();
            await(() -> reports.stream().anyMatch(r -> r.startsWith("bus: kein Servo an ")), "the silence reported");
            assertTrue(reports.stream().anyMatch(r -> r.contains(" (der Roboter antwortet seit ")
                    && r.contains("; die Servos halten ihr letztes Ziel; es wird gewartet, bis sie wieder antworten")), reports.toString());
            driver.emergencyStop();
            assertTrue(reports.stream().anyMatch(r -> r.startsWith("bus: Not-Aus gesendet, aber nicht bestätigt: seit ")
                    && r.endsWith(" hat kein Servo geantwortet; schalte die Stromversorgung der Servos aus")), reports.toString());
        } finally {
            Lang.use(Locale.ENGLISH);
        }
    }
}
