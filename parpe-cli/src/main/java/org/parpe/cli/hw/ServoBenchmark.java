package org.parpe.cli.hw;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import org.parpe.cli.bench.Benchmark;
import org.parpe.core.diag.SourcePos;
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
 * {@code parpe bench --only servo}. First, for each protocol (dxl2, sts, scs) with 18 and 55
 * servos at 1 Mbaud, the full host cycle of a run: Sync Write of every goal, then every present
 * position read back (Dynamixel: Fast Sync Read, as the emulated X series' firmware has it, once
 * each servo answered a Ping as a run's set-up pings it; STS: Sync Read; SCS, which has none, one
 * Read per servo), back to back through
 * an emulator on a {@link HalfDuplexLine} that gives every byte of both directions its line time.
 * Printed: cycles per second, the wire limit from the bytes counted on the line per cycle at ten
 * bits a byte, their ratio, and the CPU time of the driving thread per cycle (ThreadMXBean; reply
 * decoding runs on the bus's reader thread and is not in it), the median and the highest of nine
 * windows, after a warm-up of up to 20 000 cycles on a faster line, so that the host's code is
 * compiled as in a run of a minute or more. Then the older Dynamixel 2.0 Sync Write of goal positions for 8 and 55
 * XL430 servos at 1 Mbaud, into the emulator. (1) Sync Writes per second of the whole run driver
 * (bus thread, Sync Reads included) through a line that drains at 1 Mbaud, against the wire
 * limit of the Sync Write alone; (2) raw Sync Writes per second through a socat pty (no baud
 * limit). Replies cost no wire time on the drained line, so (1) is the host's side only. About 45 s in all.
 */
public final class ServoBenchmark implements Benchmark {
    private static final int BAUD = 1_000_000;
    private static final int[] CYCLE_SERVOS = {18, 55};
    private static final int CPU_WINDOWS = 9;
    private static final int WARM_UP_CYCLES = 20_000;
    private static final double WARM_UP_SECONDS = 3;

    private final double cycleSeconds;
    private final boolean cyclesOnly;

    /** The full benchmark, about 45 s. */
    public ServoBenchmark() {
        this(3.0, false);
    }

    /** {@code cycleSeconds} per cycle measurement; only those when {@code cyclesOnly} (for a smoke test). */
    ServoBenchmark(double cycleSeconds, boolean cyclesOnly) {
        this.cycleSeconds = cycleSeconds;
        this.cyclesOnly = cyclesOnly;
    }

    @Override
    public String name() {
        return "servo";
    }

    /** docs/hardware-profile.md: at most 50 µs of the host's CPU per full cycle. */
    @Override
    public List<org.parpe.cli.bench.Goal> goals() {
        return List.of(org.parpe.cli.bench.Goal.atMost("servo.*.cpu_us_per_cycle", 50));
    }

    @Override
    public void run(PrintStream out) throws Exception {
        for (String model : new String[] {"xl430-w250", "sts3215", "scs0009"}) {
            for (int n : CYCLE_SERVOS) {
                cycles(out, ServoModel.named(model), n, cycleSeconds);
            }
        }
        if (cyclesOnly) {
            return;
        }
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

    /**
     * Full cycles, as fast as the host and the simulated 1 Mbaud line allow, after a warm-up on
     * a line a hundred times faster: a 55-servo cycle takes 12 ms at 1 Mbaud, so a warm-up on
     * the slow line would measure the host's code still interpreted (the JIT compiles a method
     * after some thousands of calls, which a real run reaches in its first minute).
     */
    private static void cycles(PrintStream out, ServoModel model, int n, double seconds) throws Exception {
        String key = "servo." + model.protocol().key() + ".n" + n + ".";
        int[] ids = ids(n);
        ServoModel[] models = new ServoModel[n];
        java.util.Arrays.fill(models, model);
        int[] ticks = new int[n];
        double[] degrees = new double[n];
        int[] errors = new int[n];
        warmUp(model, ids, models, ticks, degrees, errors, seconds);
        HalfDuplexLine line = HalfDuplexLine.open(BAUD, "line");
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        try (ServoEmulator emu = fastReplies(ServoEmulator.start(line::servos, model, EmulatorOptions.of(ids),
                new EmulatorListener() { }));
             ControlTableBus bus = new ControlTableBus(model.protocol(), line.host(), BAUD, 20)) {
            pingAll(bus, ids);
            long warmEnd = System.nanoTime() + Math.min(300_000_000L, (long) (seconds * 0.25e9));
            long k = 0;
            while (System.nanoTime() < warmEnd) {
                cycle(bus, model, ids, models, ticks, degrees, errors, n, k++);
            }
            long timeouts0 = bus.counters().timeouts();
            long bytes0 = line.bytes();
            long t0 = System.nanoTime();
            long cycles = 0;
            // CPU per cycle in several windows: one context switch more or less per cycle, which
            // is most of the cost, varies with the machine's other load; the median is reported.
            double[] cpuPerCycle = new double[CPU_WINDOWS];
            for (int w = 0; w < CPU_WINDOWS; w++) {
                long cpu0 = mx.getCurrentThreadCpuTime();
                long end = System.nanoTime() + (long) (seconds / CPU_WINDOWS * 1e9);
                long c = 0;
                do {
                    cycle(bus, model, ids, models, ticks, degrees, errors, n, k++);
                    c++;
                } while (System.nanoTime() < end);
                cpuPerCycle[w] = (mx.getCurrentThreadCpuTime() - cpu0) / 1e3 / c;
                cycles += c;
            }
            long elapsed = System.nanoTime() - t0;
            java.util.Arrays.sort(cpuPerCycle);
            double bytesPerCycle = (double) (line.bytes() - bytes0) / cycles;
            double fps = cycles / (elapsed / 1e9);
            double limit = BAUD / 10.0 / bytesPerCycle;
            print(out, key + "bytes_per_cycle", bytesPerCycle);
            print(out, key + "cycle_fps", fps);
            print(out, key + "wire_limit_fps", limit);
            print(out, key + "fraction", fps / limit);
            print(out, key + "cpu_us_per_cycle", cpuPerCycle[CPU_WINDOWS / 2]);
            print(out, key + "cpu_us_per_cycle_max", cpuPerCycle[CPU_WINDOWS - 1]);
            // A timeout costs the read timeout (20 ms): a stall of the host, not the line; shown so
            // that a low fraction can be told apart from a slow host cycle.
            print(out, key + "timeouts", bus.counters().timeouts() - timeouts0);
            checkClean(emu);
        }
    }

    /** Cycles on a line a hundred times faster than the measured one, until the JIT has compiled the host's code. */
    private static void warmUp(ServoModel model, int[] ids, ServoModel[] models, int[] ticks, double[] degrees, int[] errors,
                               double seconds) throws Exception {
        int n = ids.length;
        HalfDuplexLine fast = HalfDuplexLine.open(100 * BAUD, "warm-up");
        try (ServoEmulator emu = fastReplies(ServoEmulator.start(fast::servos, model, EmulatorOptions.of(ids),
                new EmulatorListener() { }));
             ControlTableBus bus = new ControlTableBus(model.protocol(), fast.host(), 100 * BAUD, 20)) {
            pingAll(bus, ids);
            long warmEnd = System.nanoTime() + (long) (Math.min(WARM_UP_SECONDS, seconds) * 1e9);
            for (long k = 0; k < WARM_UP_CYCLES && System.nanoTime() < warmEnd; k++) {
                cycle(bus, model, ids, models, ticks, degrees, errors, n, k);
            }
            checkClean(emu);
        }
    }

    /** Pings every servo, as a run's set-up does: the bus learns each one's firmware. */
    private static void pingAll(ControlTableBus bus, int[] ids) throws java.io.IOException {
        for (int id : ids) {
            if (bus.ping(id, 3) < 0) {
                throw new IllegalStateException("emulated servo " + id + " did not answer a Ping");
            }
        }
    }

    /** One cycle: every goal by Sync Write, every present position read back. */
    private static void cycle(ControlTableBus bus, ServoModel model, int[] ids, ServoModel[] models, int[] ticks,
                              double[] degrees, int[] errors, int n, long k) throws java.io.IOException {
        ticks[(int) (k % n)] = model.ticks((k % 1800) / 20.0 - 45);
        bus.writeGoalsAndRead(ids, models, ticks, n, degrees, errors);
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
        try (ServoEmulator emu = fastReplies(ServoEmulator.start(() -> pipe[1], model, EmulatorOptions.of(ids(n)),
                counter(writes)));
             ServoDriver d = ServoDriver.open(() -> new WireLink(pipe[0], BAUD), BusConfig.defaults().withBaud(BAUD),
                     profile, modules, BusReport.lines(m -> { }))) {
            d.discover();
            double rate = PacedProducer.drive(d, modules, seconds, writes);
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

    /**
     * Return Delay Time 0, as a bus tuned for speed has it (Dynamixel servos leave the factory at
     * 500 µs, which alone would cost 9 ms per 18-servo cycle): the benchmark measures the host.
     */
    private static ServoEmulator fastReplies(ServoEmulator emu) {
        emu.returnDelay(0);
        return emu;
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
