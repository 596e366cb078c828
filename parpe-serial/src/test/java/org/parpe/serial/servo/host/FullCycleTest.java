package org.parpe.serial.servo.host;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.link.PipeLink;
import org.parpe.serial.link.WatchedLink;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.emu.ServoEmulator;

/**
 * {@code writeGoalsAndRead}: the goals reach the servos and the positions come back as with a
 * Sync Write followed by a read, but the goals leave in the same write as the read request.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class FullCycleTest {
    static final int[] IDS = {1, 2, 3, 4};

    @ParameterizedTest
    @ValueSource(strings = {"xl430-w250", "sts3215", "scs0009", "xl430-w250+xl-320"})
    void goalsLeaveWithTheReadRequestInOneWrite(String names) throws Exception {
        String[] parts = names.split("\\+");
        ServoModel[] models = new ServoModel[IDS.length];
        for (int i = 0; i < IDS.length; i++) {
            models[i] = ServoModel.named(parts[i % parts.length]);
        }
        PipeLink[] pipe = PipeLink.pair("cycle");
        AtomicInteger writes = new AtomicInteger();
        ByteLink host = new WatchedLink(pipe[0], (b, off, len) -> writes.incrementAndGet() > 0);
        try (ServoEmulator emu = ServoEmulator.start(() -> pipe[1], models, EmulatorOptions.of(IDS),
                new EmulatorListener() { });
             ControlTableBus bus = new ControlTableBus(models[0].protocol(), host, 1_000_000, 50)) {
            bus.torque(IDS, models, IDS.length, true);
            int[] ticks = new int[IDS.length];
            for (int i = 0; i < IDS.length; i++) {
                ticks[i] = models[i].ticks(12.0 * (i + 1) - 25);
            }
            double[] deg = new double[IDS.length];
            int[] err = new int[IDS.length];
            int before = writes.get();
            assertEquals(IDS.length, bus.writeGoalsAndRead(IDS, models, ticks, IDS.length, deg, err));
            // One write for goals and read together, except SCS, which reads servo by servo.
            int expected = models[0].protocol().key().equals("scs") ? IDS.length : 1;
            assertEquals(expected, writes.get() - before, "writes for one cycle");
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
            while (!arrived(bus, models, ticks, deg, err)) {
                if (System.nanoTime() > deadline) {
                    throw new AssertionError("the servos did not reach their goals in 5 s: " + java.util.Arrays.toString(deg));
                }
                Thread.sleep(5);
            }
            for (int i = 0; i < IDS.length; i++) {
                assertEquals(12.0 * (i + 1) - 25, emu.angle(IDS[i]), 0.3, "emulated servo " + IDS[i]);
                assertEquals(0, err[i], "error byte of servo " + IDS[i]);
            }
        }
    }

    private static boolean arrived(ControlTableBus bus, ServoModel[] models, int[] ticks, double[] deg, int[] err)
            throws IOException {
        bus.writeGoalsAndRead(IDS, models, ticks, IDS.length, deg, err);
        for (int i = 0; i < IDS.length; i++) {
            if (Math.abs(deg[i] - (12.0 * (i + 1) - 25)) > 0.3) {
                return false;
            }
        }
        return true;
    }
}
