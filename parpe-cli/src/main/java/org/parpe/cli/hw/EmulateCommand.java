package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Function;
import org.parpe.cli.options.OutputFile;
import org.parpe.cli.options.ReadsInput;
import org.parpe.cli.options.UsageException;
import org.parpe.serial.g1.emu.BusEmulator;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code parpe emulate}: serves the bus protocol on a serial device as a chain of G1-style modules
 * would, with injected faults. Lines on standard input pose limp modules by hand
 * ({@code pose ID DEG}), press touch sensors ({@code touch ID left|right|both|none}) or print the
 * modules' state ({@code status}).
 */
@Command(name = "emulate", mixinStandardHelpOptions = true, description = {"Emulate PolyBot modules, Dynamixel 2.0 or Feetech servos on a serial device "
    + "(e.g. one end of a socat pty pair).",
    "Standard input takes: pose ID DEG | touch ID left|right|both|none (G1) | fault ID overload|overheat|voltage|none "
    + "(servos) | status | quit."})
public final class EmulateCommand implements ReadsInput, Callable<Integer> {
    @Option(names = "--port", required = true, paramLabel = "PATH", description = "The serial device to serve.")
    String port;

    @Option(names = "--modules", defaultValue = "0..7", paramLabel = "IDS",
            description = "Module IDs to emulate, e.g. 0..7 or 0,2,4 (default ${DEFAULT-VALUE}).")
    String modules;

    @Option(names = "--baud", paramLabel = "N",
            description = "Line speed (default: the protocol's, 115200 for g1, 57600 for dxl2, 1000000 for sts and scs).")
    Integer baud;

    @Option(names = "--protocol", defaultValue = "g1", paramLabel = "g1|dxl2|sts|scs",
            description = "Bus protocol: PARPE's G1 modules, Dynamixel 2.0 or Feetech STS/SCS servos (default ${DEFAULT-VALUE}).")
    String protocol;

    @Option(names = "--model", paramLabel = "NAME",
            description = "Servo model for dxl2/sts/scs, e.g. xl430-w250, xm430-w210, xl330-m288, sts3215 (default: the protocol's first).")
    String model;

    @Option(names = "--drop", defaultValue = "0", paramLabel = "P", description = "Probability of losing a frame, each direction.")
    double drop;

    @Option(names = "--corrupt", defaultValue = "0", paramLabel = "P", description = "Probability of one wrong byte in a frame, each direction.")
    double corrupt;

    @Option(names = "--latency", defaultValue = "0", paramLabel = "MS", description = "Delay before each reply.")
    double latency;

    @Option(names = "--unplug-after", paramLabel = "S", description = "Pull the cable this many seconds after start.")
    Double unplugAfter;

    @Option(names = "--unplug-for", paramLabel = "S", description = "Plug it back after this many seconds (default: never).")
    Double unplugFor;

    @Option(names = "--speed", defaultValue = "360", paramLabel = "DEG/S", description = "Servo speed limit (default ${DEFAULT-VALUE}).")
    double speed;

    @Option(names = "--seed", defaultValue = "1", paramLabel = "N", description = "Seed of the fault injector.")
    long seed;

    @Option(names = "--log", paramLabel = "FILE", description = "Write every setpoint frame received as CSV (seq,m<ID>,...).")
    Path log;

    @Option(names = "--duration", paramLabel = "S", description = "Stop after this many seconds (default: at Ctrl-C or quit).")
    Double duration;

    @Spec
    CommandSpec spec;

    /** Standard input, or what the command line was handed instead ({@link ReadsInput}). */
    private InputStream input = System.in;

    @Override
    public void readFrom(InputStream in) {
        input = in;
    }

    @Override
    public Integer call() throws Exception {
        return serve(spec.commandLine().getErr());
    }

    private EmulatorOptions options(int[] ids) throws UsageException {
        if (baud != null && baud <= 0) {
            throw new UsageException(CliMsg.BAUD_POSITIVE.text(baud));
        }
        if (unplugFor != null && unplugAfter == null) {
            throw new UsageException(CliMsg.UNPLUG_FOR_NEEDS_AFTER.text());
        }
        if (unplugAfter != null && !(unplugAfter >= 0) || unplugFor != null && !(unplugFor >= 0)) {
            throw new UsageException(CliMsg.UNPLUG_NEGATIVE.text());
        }
        if (duration != null && !(duration > 0)) {
            throw new UsageException(CliMsg.DURATION_NOT_POSITIVE.text(duration));
        }
        try {
            return new EmulatorOptions(ids, drop, corrupt, latency, unplugAfter == null ? -1 : unplugAfter,
                    unplugFor == null ? -1 : unplugFor, speed, seed);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
    }

    private int serve(PrintWriter err) throws UsageException, InterruptedException {
        int[] ids = ModuleList.sorted(ModuleList.parse(modules, "--modules"));
        EmulatorOptions o = options(ids);
        ServoProtocol p = ServoProtocol.of(protocol);
        if (p == null) {
            throw new UsageException(CliMsg.BAD_PROTOCOL.text(ServoProtocol.keys(), protocol));
        }
        int rate = baud == null ? p.scanBauds().get(0) : baud;
        if (p.controlTable()) {
            return new ServoEmulation(port, rate, servoModel(p), o, duration, log, err).serve(input);
        }
        if (model != null) {
            throw new UsageException(CliMsg.MODEL_NOT_FOR_G1.text());
        }
        SetpointLog csv = SetpointLog.open(log, ids);
        BusEmulator emu;
        try {
            emu = BusEmulator.start(LinkOpener.serial(port, rate), o, listener(err, csv));
        } catch (IOException e) {
            csv.close();
            throw new UsageException(e.getMessage());
        }
        err.println("emulate: " + CliMsg.EMULATING_MODULES.text(ids.length, ModuleList.format(ids), port, rate));
        return serveUntilDone(() -> {
            emu.close();
            csv.close();
            BusEmulator.Stats s = emu.stats();
            err.println("emulate: " + CliMsg.G1_EMULATION_STATS.text(s.frames(), s.checksumErrors(), s.dropped(),
                    s.corrupted(), s.replies()));
        }, w -> ConsoleCommands.apply(ConsoleCommands.of(emu), w), duration, input, err);
    }

    private ServoModel servoModel(ServoProtocol p) throws UsageException {
        if (model == null) {
            return ServoModel.defaultFor(p);
        }
        ServoModel m = ServoModel.named(model);
        if (m == null || m.protocol() != p) {
            throw new UsageException(CliMsg.UNKNOWN_MODEL.text(model, p.key(), ServoModel.names(p)));
        }
        return m;
    }

    static EmulatorListener listener(PrintWriter err, SetpointLog csv) {
        return new EmulatorListener() {
            @Override
            public void onSetpoints(int seq, double[] angles) {
                csv.write(seq, angles);
            }

            @Override
            public void onSafeStop(int id, long nanoTime, String why) {
                err.println("emulate: " + CliMsg.MODULE_STOPPED.text(id, why));
            }

            @Override
            public void onEvent(String message) {
                err.println(message);
            }
        };
    }

    /**
     * Serves until {@code quit} on {@code input} (the command's standard input), the end of {@code duration} seconds (null: no
     * end) or Ctrl-C, answering console lines with {@code commands}; then runs
     * {@code closeAndReport} once, whichever came first. Returns the exit code 0.
     */
    static int serveUntilDone(Runnable closeAndReport, Function<String[], String> commands, Double duration,
                              InputStream input, PrintWriter err) throws InterruptedException {
        CountDownLatch done = new CountDownLatch(1);
        AtomicBoolean closed = new AtomicBoolean();
        Runnable shutdown = () -> {
            if (closed.compareAndSet(false, true)) {
                closeAndReport.run();
            }
        };
        Thread hook = new Thread(shutdown, "emulate-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        Thread console = new Thread(() -> console(input, commands, err, done), "emulate-console");
        console.setDaemon(true);
        console.start();
        if (duration != null) {
            done.await((long) (duration * 1000), TimeUnit.MILLISECONDS);
        } else {
            done.await();
        }
        shutdown.run();
        Runtime.getRuntime().removeShutdownHook(hook);
        return 0;
    }

    /** Reads commands from {@code input}; end of input only stops the console, not the emulator. */
    private static void console(InputStream input, Function<String[], String> commands, PrintWriter err,
                                CountDownLatch done) {
        BufferedReader in = new BufferedReader(new InputStreamReader(input, StandardCharsets.UTF_8));
        try {
            for (String line; (line = in.readLine()) != null; ) {
                String[] w = line.trim().split("\\s+");
                if (w[0].equals("quit")) {
                    done.countDown();
                    return;
                }
                if (!w[0].isEmpty()) {
                    err.println(commands.apply(w));
                }
            }
        } catch (IOException e) {
            err.println("emulate: " + CliMsg.STANDARD_INPUT.text(e.getMessage()));
        }
    }

    /** The CSV log of received setpoints. */
    static final class SetpointLog {
        private final Writer out;
        private final StringBuilder row = new StringBuilder();

        private SetpointLog(Writer out) {
            this.out = out;
        }

        /** Opens the log through the output rules (docs/cli.md): it replaces {@code file} when the emulator stops. */
        static SetpointLog open(Path file, int[] ids) throws UsageException {
            if (file == null) {
                return new SetpointLog(null);
            }
            OutputFile target = OutputFile.of(OutputFile.plan(List.of()), "--log", file.toString());
            Writer w = target.openWriter();
            try {
                StringBuilder h = new StringBuilder("seq");
                for (int id : ids) {
                    h.append(",m").append(id);
                }
                w.write(h.append('\n').toString());
                return new SetpointLog(w);
            } catch (IOException e) {
                OutputFile.abort(w);
                throw new UsageException(e.getMessage());
            }
        }

        synchronized void write(int seq, double[] angles) {
            if (out == null) {
                return;
            }
            row.setLength(0);
            row.append(seq);
            for (double a : angles) {
                row.append(',');
                if (!Double.isNaN(a)) {
                    row.append(String.format(Locale.ROOT, "%.2f", a));
                }
            }
            try {
                out.write(row.append('\n').toString());
            } catch (IOException e) {
                // A full disk must not stop the emulated modules; the log just ends early.
            }
        }

        synchronized void close() {
            try {
                if (out != null) {
                    out.close();
                }
            } catch (IOException e) {
                // Nothing more can be done about a log that cannot be closed: what was there stays.
            } finally {
                OutputFile.abort(out);
            }
        }
    }
}
