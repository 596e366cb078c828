package org.parpe.cli.hw;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.parpe.cli.bench.Benchmark;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.RunOutcome;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.BusReport;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.PipeLink;
import org.parpe.serial.link.PtyPair;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.emu.ServoEmulator;
import org.parpe.serial.servo.host.ControlTableBus;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ServoMapping;
import org.parpe.serial.servo.run.ServoDriver;

/**
 * {@code parpe bench --only servo}: Dynamixel 2.0 Sync Write of goal positions for 8 and 55
 * XL430 servos at 1 Mbaud, into the emulator. (1) Sync Writes per second of the whole run driver
 * (bus thread, Sync Reads included) through a line that drains at 1 Mbaud, against the wire
 * limit of the Sync Write alone; (2) raw Sync Writes per second through a socat pty (no baud
 * limit). Replies cost no wire time on the drained line, so (1) is the host's side only. About 12 s.
 */
public final class ServoBenchmark implements Benchmark {
    private static final int BAUD = 1_000_000;
    private static final long PRODUCER_NANOS = 500_000;

    @Override
    public String name() {
        return "servo";
    }

    @Override
    public void run(PrintStream out) throws Exception {
        ServoModel xl430 = ServoModel.named("xl430-w250");
        for (int n : new int[] {8, 55}) {
            // Header, ID, length (7) + instruction (1) + address and data length (4) + n × (ID + 4 bytes) + CRC (2).
            int packet = 14 + 5 * n;
            double limit = BAUD / 10.0 / packet;
            print(out, "servo.dxl2_syncwrite_bytes_" + n, packet);
            print(out, "servo.dxl2_wire_limit_per_s_" + n, limit);
            double driver = driver(xl430, n, 4.0);
            print(out, "servo.dxl2_driver_syncwrites_per_s_" + n, driver);
            print(out, "servo.dxl2_driver_fraction_of_wire_" + n, driver / limit);
            pty(out, xl430, n);
        }
    }

    private static int[] ids(int n) {
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            ids[i] = i + 1;
        }
        return ids;
    }

    /** The run driver over a line draining at 1 Mbaud, a producer offering setpoints every 0.5 ms. */
    private static double driver(ServoModel model, int n, double seconds) throws Exception {
        PipeLink[] pipe = PipeLink.pair("bench");
        AtomicLong writes = new AtomicLong();
        List<ServoMapping> servos = new ArrayList<>();
        int[] modules = new int[n];
        for (int i = 0; i < n; i++) {
            modules[i] = i;
            servos.add(new ServoMapping(i, i + 1, model, 0, 1, -90, 90, SourcePos.NONE));
        }
        HardwareProfile profile = new HardwareProfile("bench", ServoProtocol.DXL2, "bench", BAUD, SafeMode.HOLD, 0,
                servos);
        try (ServoEmulator emu = ServoEmulator.start(() -> pipe[1], model, EmulatorOptions.of(ids(n)), counter(writes));
             ServoDriver d = ServoDriver.open(() -> new WireLink(pipe[0], BAUD), BusConfig.defaults().withBaud(BAUD),
                     profile, modules, BusReport.lines(m -> { }))) {
            d.discover();
            d.start(new RunInfo(null, modules, 0.01));
            double[] row = new double[n];
            long end = System.nanoTime() + (long) (seconds * 1e9);
            long warm = System.nanoTime() + 500_000_000L;
            long startWrites = -1;
            long start = 0;
            for (long k = 0; System.nanoTime() < end; k++) {
                if (startWrites < 0 && System.nanoTime() > warm) {
                    startWrites = writes.get();
                    start = System.nanoTime();
                }
                row[(int) (k % n)] = (k % 1800) / 20.0 - 45;
                d.accept(k, k * 0.01, row);
                LockSupport.parkNanos(PRODUCER_NANOS);
            }
            double rate = (writes.get() - startWrites) / ((System.nanoTime() - start) / 1e9);
            d.finish(new RunOutcome(RunOutcome.Status.COMPLETED, 0, ""));
            checkClean(emu);
            return rate;
        }
    }

    /** Back-to-back Sync Writes through a socat pty into the emulator. */
    private static void pty(PrintStream out, ServoModel model, int n) throws Exception {
        if (!PtyPair.available()) {
            out.println("servo.dxl2_pty_syncwrites_per_s_" + n + "=skipped (socat is not installed)");
            return;
        }
        Path dir = Files.createTempDirectory("parpe-bench");
        AtomicLong writes = new AtomicLong();
        int[] ids = ids(n);
        ServoModel[] models = new ServoModel[n];
        java.util.Arrays.fill(models, model);
        int[] ticks = new int[n];
        try (PtyPair pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"));
             ServoEmulator emu = ServoEmulator.start(LinkOpener.serial(pty.b().toString(), BAUD), model,
                     EmulatorOptions.of(ids), counter(writes));
             ControlTableBus bus = new ControlTableBus(ServoProtocol.DXL2,
                     LinkOpener.serial(pty.a().toString(), BAUD).open(), BAUD, 20)) {
            long sent = 0;
            long w0 = 0;
            long f0 = 0;
            long end = System.nanoTime() + 3_500_000_000L;
            for (long k = 0; System.nanoTime() < end; k++) {
                if (k == 2000) {
                    f0 = writes.get();
                    w0 = System.nanoTime();
                }
                ticks[(int) (k % n)] = model.ticks((k % 1800) / 20.0 - 45);
                bus.writeGoals(ids, models, ticks, n);
                sent++;
            }
            Thread.sleep(200);
            double rate = (writes.get() - f0) / ((System.nanoTime() - w0 - 200e6) / 1e9);
            print(out, "servo.dxl2_pty_syncwrites_per_s_" + n, rate);
            print(out, "servo.dxl2_pty_received_fraction_" + n, (double) writes.get() / sent);
            checkClean(emu);
        } finally {
            Files.deleteIfExists(dir);
        }
    }

    /** A benchmark on a damaged line would measure the wrong thing. */
    private static void checkClean(ServoEmulator emu) {
        if (emu.stats().checksumErrors() > 0) {
            throw new IllegalStateException("the emulator rejected " + emu.stats().checksumErrors() + " packets");
        }
    }

    private static EmulatorListener counter(AtomicLong writes) {
        return new EmulatorListener() {
            @Override
            public void onSetpoints(int seq, double[] angles) {
                writes.incrementAndGet();
            }
        };
    }

    private static void print(PrintStream out, String name, double v) {
        out.println(name + "=" + (v == Math.rint(v) && Math.abs(v) < 1e15 ? String.valueOf((long) v)
                : String.format(Locale.ROOT, "%.3f", v)));
    }
}
