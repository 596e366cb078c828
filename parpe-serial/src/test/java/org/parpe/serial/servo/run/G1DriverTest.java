package org.parpe.serial.servo.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.stream.IntStream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.RunOutcome;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.BusReport;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.g1.emu.BusEmulator;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.OverPty;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ServoMapping;

/**
 * The run driver with a G1 profile against emulated G1 modules over a socat pty. G1 has no group
 * read: each module is one READ transaction, waiting for its reply.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class G1DriverTest extends OverPty {
    static final int[] MODULES = IntStream.rangeClosed(1, 20).toArray();

    BusEmulator g1;
    ServoDriver driver;
    final List<String> reports = new CopyOnWriteArrayList<>();

    @BeforeEach
    void open() throws Exception {
        g1 = BusEmulator.start(LinkOpener.serial(pty.b().toString(), 115_200), EmulatorOptions.of(MODULES),
                new EmulatorListener() { });
        ServoModel model = ServoModel.defaultFor(ServoProtocol.G1);
        List<ServoMapping> servos = new ArrayList<>();
        for (int m : MODULES) {
            servos.add(new ServoMapping(m, m, model, 0, 1, -90, 90, SourcePos.NONE));
        }
        HardwareProfile profile = new HardwareProfile("test", ServoProtocol.G1, pty.a().toString(), 115_200,
                SafeMode.HOLD, HardwareProfile.DEFAULT_WATCHDOG_MS, servos);
        driver = ServoDriver.open(LinkOpener.serial(pty.a().toString(), 115_200), BusConfig.defaults(), profile,
                MODULES, BusReport.lines(reports::add));
        List<Integer> all = IntStream.of(MODULES).boxed().toList();
        // A fresh emulator loads its classes on its first frames: discovery's retries may not be enough.
        for (int a = 0; a < 5 && !driver.discover().equals(all); a++) {
            Thread.sleep(200);
        }
        assertEquals(all, driver.discover(), reports.toString());
    }

    @Override
    protected AutoCloseable[] openEnds() {
        return new AutoCloseable[] {driver, g1};
    }

    @Test
    void aReadCycleReadsOneModuleNotAll() throws Exception {
        // Reading every module each read cycle, as for Dynamixel's Sync Read, made 20 G1 modules
        // 20 READ transactions between two setpoint frames (55 modules about 120 ms at 115 200
        // baud), where --port reads one per cycle, round robin. Failed before: 20 replies per cycle.
        long before = g1.stats().replies();
        for (int c = 0; c < 5; c++) {
            driver.cycle();
        }
        long replies = g1.stats().replies() - before;
        assertTrue(replies >= 1 && replies < MODULES.length, replies + " READ replies in 5 cycles");
    }

    @Test
    void aModuleStoppedOnItsWatchdogIsResumedWhenItIsRead() throws Exception {
        // --port resumes a module as soon as a read shows its watchdog latch; the servo driver
        // checked one servo per 100 ms, so 20 modules stayed stopped for up to 2 s. Failed before.
        double[] angles = new double[MODULES.length];
        java.util.Arrays.fill(angles, 5);
        driver.accept(0, 0, angles);
        driver.cycle();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (!IntStream.of(MODULES).allMatch(g1::isSafeStopped)) {
            assertTrue(System.nanoTime() < deadline, "every module stopped on its watchdog without frames");
            Thread.sleep(10);
        }
        // Four rounds of reads, in case a reply is late on a loaded machine; the old check of one
        // servo per 100 ms resumed only a few modules in that many cycles.
        for (int c = 0; c < 4 * MODULES.length; c++) {
            driver.cycle();
        }
        // Counted in the reports, not in the emulator's state: a test thread paused for more than
        // the modules' 50 ms watchdog would let them stop again after their RESUME.
        for (int id : MODULES) {
            assertTrue(reports.contains("bus: module " + id + " had stopped on its watchdog (a gap of more than "
                    + HardwareProfile.DEFAULT_WATCHDOG_MS + " ms in the bus traffic); resuming it"),
                    "module " + id + " resumed within four rounds of reads: " + reports);
        }
    }

    @Test
    void roundRobinReadsReachEveryModule() throws Exception {
        driver.start(new RunInfo(null, MODULES, 0.01));
        double[] angles = new double[MODULES.length];
        java.util.Arrays.fill(angles, 10);
        driver.accept(0, 0, angles);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        for (int i = 0; i < MODULES.length; i++) {
            while (Math.abs(driver.measuredAngle(i) - 10) > 0.1) {
                assertTrue(System.nanoTime() < deadline, "module " + MODULES[i] + " measured at 10° within 10 s: "
                        + driver.measuredAngle(i));
                Thread.sleep(5);
            }
        }
        driver.finish(new RunOutcome(RunOutcome.Status.COMPLETED, 0, ""));
        assertTrue(reports.get(reports.size() - 1).contains("0 disconnects"), reports.toString());
    }
}
