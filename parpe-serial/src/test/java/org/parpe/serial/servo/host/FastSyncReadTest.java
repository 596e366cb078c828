package org.parpe.serial.servo.host;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.link.PipeLink;
import org.parpe.serial.link.WatchedLink;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.emu.ServoEmulator;
import org.parpe.serial.servo.wire.PacketCodec;

/**
 * The host reads positions by Dynamixel Fast Sync Read (ROBOTIS e-Manual, Protocol 2.0, Fast Sync
 * Read (0x8A): one status packet for all servos instead of one per servo) where every servo read
 * has it, as its model and the firmware its Ping reported say (X series from v45), and by Sync
 * Read (0x82) otherwise.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class FastSyncReadTest {
    static final int[] IDS = {1, 2, 3, 4};
    /** The instruction byte of every packet the host wrote (Dynamixel 2.0: offset 7). */
    final List<Integer> sent = new ArrayList<>();

    ServoEmulator emu;
    ControlTableBus bus;

    void start(ServoModel model) throws java.io.IOException {
        PipeLink[] pipe = PipeLink.pair("fast");
        ByteLink host = new WatchedLink(pipe[0], (b, off, len) -> {
            synchronized (sent) {
                // A write may hold two packets (goals with the read request).
                for (int i = off; i + 7 < off + len; i++) {
                    if ((b[i] & 0xFF) == 0xFF && (b[i + 1] & 0xFF) == 0xFF && (b[i + 2] & 0xFF) == 0xFD
                            && b[i + 3] == 0) {
                        sent.add(b[i + 7] & 0xFF);
                    }
                }
            }
            return true;
        });
        ServoModel[] models = new ServoModel[IDS.length];
        Arrays.fill(models, model);
        emu = ServoEmulator.start(() -> pipe[1], models, EmulatorOptions.of(IDS), new EmulatorListener() { });
        bus = new ControlTableBus(model.protocol(), host, 1_000_000, 50);
    }

    void stop() {
        bus.close();
        emu.close();
    }

    /** Reads the four servos' positions; returns the instruction of the read request(s) sent. */
    List<Integer> read(ServoModel model, double[] deg, int[] err) throws Exception {
        ServoModel[] models = new ServoModel[IDS.length];
        Arrays.fill(models, model);
        synchronized (sent) {
            sent.clear();
        }
        bus.readPositions(IDS, models, IDS.length, deg, err);
        synchronized (sent) {
            return List.copyOf(sent);
        }
    }

    @Test
    void xSeriesServosWhosePingReportedV45OrLaterAreReadByFastSyncRead() throws Exception {
        ServoModel m = ServoModel.named("xm430-w210");
        start(m);
        try {
            double[] deg = new double[IDS.length];
            int[] err = new int[IDS.length];
            assertEquals(List.of(PacketCodec.SYNC_READ), read(m, deg, err), "firmware not known before a Ping");
            for (int i = 0; i < IDS.length; i++) {
                assertTrue(emu.backDrive(IDS[i], 10.0 * i - 15), "servo " + IDS[i] + " limp");
                assertEquals(m.number(), bus.ping(IDS[i], 3));
            }
            assertEquals(List.of(PacketCodec.FAST_SYNC_READ), read(m, deg, err));
            for (int i = 0; i < IDS.length; i++) {
                assertEquals(0, err[i], "servo " + IDS[i]);
                assertEquals(10.0 * i - 15, deg[i], m.degreesPerTick(), "servo " + IDS[i]);
            }
        } finally {
            stop();
        }
    }

    @Test
    void aServoModelWithoutFastSyncReadIsReadBySyncRead() throws Exception {
        ServoModel m = ServoModel.named("xl-320");
        start(m);
        try {
            for (int id : IDS) {
                assertEquals(m.number(), bus.ping(id, 3));
            }
            double[] deg = new double[IDS.length];
            int[] err = new int[IDS.length];
            assertEquals(List.of(PacketCodec.SYNC_READ), read(m, deg, err));
            assertTrue(Arrays.stream(err).allMatch(e -> e == 0), Arrays.toString(err));
        } finally {
            stop();
        }
    }

    @Test
    void aFastSyncReadLeftUnfinishedIsReadAgainBySyncReadInTheSameCycle() throws Exception {
        // Servo 3 stops answering reads (Status Return Level 0, e-Manual X series, Status Return
        // Level(68)): the Fast Sync Read packet breaks at its block; the others are still read.
        ServoModel m = ServoModel.named("xl430-w250");
        start(m);
        try {
            for (int id : IDS) {
                assertEquals(m.number(), bus.ping(id, 3));
            }
            bus.write(3, 68, 1, 0, 1);
            double[] deg = new double[IDS.length];
            int[] err = new int[IDS.length];
            assertEquals(List.of(PacketCodec.FAST_SYNC_READ, PacketCodec.SYNC_READ), read(m, deg, err));
            assertEquals(List.of(0, 0, ServoBus.NO_REPLY, 0), Arrays.stream(err).boxed().toList());
            assertEquals(List.of(PacketCodec.SYNC_READ), read(m, deg, err), "no Fast Sync Read while one is silent");
        } finally {
            stop();
        }
    }
}
