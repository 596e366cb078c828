package org.parpe.cli.hw;

import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import org.parpe.cli.bench.Benchmark;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.g1.BusMaster;
import org.parpe.serial.bus.BusReport;
import org.parpe.serial.g1.emu.BusEmulator;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.PipeLink;
import org.parpe.serial.link.PtyPair;
import org.parpe.serial.g1.FrameDecoder;
import org.parpe.serial.g1.FrameEncoder;
import org.parpe.serial.g1.Protocol;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.run.ServoDriver;

/**
 * {@code parpe bench --only serial}: setpoint frames for 55 modules. (1) CPU per frame of the
 * encoder, the decoder, and the host's send path through a real pty; (2) frames per second of the
 * whole driver (bus thread, reads included) through a line that drains at 115 200 baud and at
 * 1 Mbaud, against the wire limit; (3) raw frames per second through a socat pty. Goals: at least
 * 90 % of the wire limit, at most 50 µs of CPU per frame. About 15 s.
 */
public final class SerialBenchmark implements Benchmark {
    private static final int MODULES = 55;
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    @Override
    public String name() {
        return "serial";
    }

    /** docs/hardware-protocol.md: the driver at 0.9 of the wire or more, at most 50 µs of CPU per frame. */
    @Override
    public java.util.List<org.parpe.cli.bench.Goal> goals() {
        return java.util.List.of(org.parpe.cli.bench.Goal.atLeast("serial.driver_fraction_of_wire_*", 0.9),
                org.parpe.cli.bench.Goal.atMost("serial.*_cpu_us_per_frame", 50));
    }

    @Override
    public void run(PrintStream out) throws Exception {
        int frame = Protocol.setpointFrameLength(MODULES);
        print(out, "serial.modules", MODULES);
        print(out, "serial.frame_bytes", frame);
        codec(out);
        for (int baud : new int[] {115_200, 1_000_000}) {
            double limit = baud / 10.0 / frame;
            double fps = driver(baud, 4.0);
            print(out, "serial.wire_limit_fps_" + baud, limit);
            print(out, "serial.driver_fps_" + baud, fps);
            print(out, "serial.driver_fraction_of_wire_" + baud, fps / limit);
        }
        pty(out, frame);
    }

    /** Encoder and decoder CPU per frame, in memory. */
    private static void codec(PrintStream out) {
        FrameEncoder enc = new FrameEncoder();
        short[] wire = new short[MODULES];
        long[] count = {0};
        FrameDecoder dec = new FrameDecoder((a, c, b, o, l) -> count[0]++);
        int n = 200_000;
        long t0 = THREADS.getCurrentThreadCpuTime();
        int len = 0;
        for (int i = 0; i < n; i++) {
            wire[i % MODULES] = (short) i;
            len = enc.setpoints(i, 0, wire, MODULES);
        }
        long t1 = THREADS.getCurrentThreadCpuTime();
        for (int i = 0; i < n; i++) {
            dec.feed(enc.buffer(), 0, len);
        }
        long t2 = THREADS.getCurrentThreadCpuTime();
        if (count[0] != n) {
            throw new IllegalStateException("decoded " + count[0] + " of " + n + " frames");
        }
        print(out, "serial.encode_cpu_us_per_frame", (t1 - t0) / 1e3 / n);
        print(out, "serial.decode_cpu_us_per_frame", (t2 - t1) / 1e3 / n);
    }

    /**
     * The driver with an emulator over an in-memory line draining at {@code baud}; a producer
     * offers new setpoints as fast as it can. Returns setpoint frames the modules got per second.
     */
    private static double driver(int baud, double seconds) throws Exception {
        BusConfig config = BusConfig.defaults().withBaud(baud);
        PipeLink[] pipe = PipeLink.pair("bench");
        AtomicLong frames = new AtomicLong();
        int[] ids = new int[MODULES];
        for (int i = 0; i < MODULES; i++) {
            ids[i] = i;
        }
        try (BusEmulator emu = BusEmulator.start(() -> pipe[1], EmulatorOptions.of(ids), new EmulatorListener() {
            @Override
            public void onSetpoints(int seq, double[] angles) {
                frames.incrementAndGet();
            }
        }); ServoDriver bus = ServoDriver.open(() -> new WireLink(pipe[0], baud), config,
                HardwareProfile.ofModules("bench", config, ids), ids, BusReport.lines(m -> { }))) {
            bus.discover();
            double fps = PacedProducer.drive(bus, ids, seconds, frames);
            checkClean(emu);
            return fps;
        }
    }

    /** Raw frames through a socat pty into the emulator, and the host's CPU per frame sent. */
    private static void pty(PrintStream out, int frame) throws Exception {
        if (!PtyPair.available()) {
            out.println("serial.pty_fps=skipped (socat is not installed)");
            return;
        }
        Path dir = Files.createTempDirectory("parpe-bench");
        AtomicLong frames = new AtomicLong();
        int[] ids = new int[MODULES];
        for (int i = 0; i < MODULES; i++) {
            ids[i] = i;
        }
        try (PtyPair pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"));
             BusEmulator emu = BusEmulator.start(LinkOpener.serial(pty.b().toString(), 115_200),
                     EmulatorOptions.of(ids), new EmulatorListener() {
                         @Override
                         public void onSetpoints(int seq, double[] angles) {
                             frames.incrementAndGet();
                         }
                     });
             BusMaster bus = new BusMaster(LinkOpener.serial(pty.a().toString(), 115_200).open(), BusConfig.defaults())) {
            short[] wire = new short[MODULES];
            sendFor(bus, wire, 0.5);
            long f0 = frames.get();
            long w0 = System.nanoTime();
            long c0 = THREADS.getCurrentThreadCpuTime();
            long sent = sendFor(bus, wire, 3.0);
            long c1 = THREADS.getCurrentThreadCpuTime();
            Thread.sleep(200);
            double fps = (frames.get() - f0) / ((System.nanoTime() - w0 - 200e6) / 1e9);
            print(out, "serial.pty_fps", fps);
            print(out, "serial.pty_fraction_of_wire_115200", fps / (115_200 / 10.0 / frame));
            print(out, "serial.pty_fraction_of_wire_1000000", fps / (1_000_000 / 10.0 / frame));
            print(out, "serial.host_send_cpu_us_per_frame", (c1 - c0) / 1e3 / sent);
            checkClean(emu);
        } finally {
            Files.deleteIfExists(dir);
        }
    }

    /** A benchmark on a damaged line would measure the wrong thing. */
    private static void checkClean(BusEmulator emu) {
        if (emu.stats().checksumErrors() > 0) {
            throw new IllegalStateException("the emulator rejected " + emu.stats().checksumErrors() + " frames");
        }
    }

    private static long sendFor(BusMaster bus, short[] wire, double seconds) throws IOException {
        long end = System.nanoTime() + (long) (seconds * 1e9);
        long n = 0;
        while (System.nanoTime() < end) {
            wire[(int) (n % MODULES)] = (short) (n % 9000);
            bus.sendSetpoints((int) n, 0, wire, MODULES);
            n++;
        }
        return n;
    }

    private static void print(PrintStream out, String name, double v) {
        out.println(name + "=" + (v == Math.rint(v) && Math.abs(v) < 1e15 ? String.valueOf((long) v)
                : String.format(Locale.ROOT, "%.3f", v)));
    }
}
