package org.parpe.cli.export;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.parpe.cli.ClockOptions;
import org.parpe.cli.Inputs;
import org.parpe.cli.ParamValues;
import org.parpe.cli.UsageException;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.export.Board;
import org.parpe.core.export.CExport;
import org.parpe.core.export.CRuntime;
import org.parpe.core.export.DriverCost;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code parpe export SCRIPT --target c|arduino --out DIR}: the script as portable C (runtime,
 * tables, a host trace program) or as an Arduino sketch folder, with a memory estimate for the
 * board. Exit codes as {@code run}: 1 script errors (also what the board cannot hold), 2 usage errors.
 */
@Command(name = "export", mixinStandardHelpOptions = true, description = "Compile a PARSL script to C99 or to an"
        + " Arduino sketch that runs it without a PC (see docs/embedded.md).")
public final class ExportCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "SCRIPT", description = "The PARSL script.")
    Path file;

    @Option(names = "--target", paramLabel = "c|arduino", defaultValue = "c",
            description = "c: runtime + tables + a host trace program; arduino: a sketch folder (default ${DEFAULT-VALUE}).")
    String target;

    @Option(names = "--out", paramLabel = "DIR", required = true, description = "Folder to write (created if missing).")
    Path out;

    @Option(names = "--tick", paramLabel = "SECONDS", defaultValue = "0.01", description = "The fixed tick (default ${DEFAULT-VALUE}).")
    double tick;

    @Option(names = "--param", paramLabel = "NAME=VALUE", description = "Bake in a parameter value (repeatable).")
    List<String> params = new ArrayList<>();

    @Option(names = "--board", paramLabel = "uno|nano|esp32|host",
            description = "Board for the memory check (default: host for c, uno for arduino).")
    String board;

    @Option(names = "--servo", paramLabel = "pwm|dxl|sts", defaultValue = "pwm",
            description = "Arduino servo driver: hobby PWM servos, Dynamixel 2.0 or Feetech STS on a UART (default ${DEFAULT-VALUE}).")
    String servo;

    @Option(names = "--pins", paramLabel = "P,...", split = ",", description = "PWM pins, one per module in ascending ID order (default 2, 3, 4, ...).")
    List<Integer> pins = new ArrayList<>();

    @Option(names = "--baud", paramLabel = "N", defaultValue = "1000000", description = "Servo bus baud rate for dxl/sts (default ${DEFAULT-VALUE}).")
    int baud;

    @Option(names = "--model", paramLabel = "NAME", description = "Servo model for dxl/sts (default xl430-w250 / sts3215).")
    String model;

    @Option(names = "--console-sensors", description = "Arduino: take accel and touch readings from console commands"
            + " ($3_touch_left=1) instead of refusing scripts that declare them.")
    boolean consoleSensors;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws UsageException {
        PrintWriter err = spec.commandLine().getErr();
        try {
            return execute(err);
        } catch (IOException e) {
            err.println("parpe: cannot write '" + out + "': " + e.getMessage());
            return 2;
        }
    }

    private int execute(PrintWriter err) throws UsageException, IOException {
        ClockOptions.check(tick, null);
        Inputs.check(file);
        boolean arduino = switch (target) {
            case "c" -> false;
            case "arduino" -> true;
            default -> throw new UsageException("--target must be c or arduino, got '" + target + "'");
        };
        Board b = board(arduino);
        if (arduino) {
            ArduinoSketch.tickMicros(tick);
        }
        SketchOptions sketch = arduino ? SketchOptions.of(servo, pins, baud, model, consoleSensors) : null;
        LoadResult r = ScriptLoader.load(file, ParamValues.parse(params));
        int refused = org.parpe.cli.LoadReport.exitCode(r, err::println);
        if (refused != 0) {
            return refused;
        }
        DiagnosticList diags = new DiagnosticList();
        if (sketch != null) {
            sketch.check(r.program(), diags);
        }
        DriverCost driver = sketch == null ? DriverCost.NONE : sketch.cost(r.program().moduleIds().length);
        CExport.Result result = diags.hasErrors() ? null : CExport.export(r.program(), tick, b, driver, diags);
        diags.all().forEach(d -> err.println(d.format()));
        if (result == null) {
            return 1;
        }
        write(r.program(), result, sketch);
        return 0;
    }

    /** The board of {@code --board}, checked against the target and the target's other options. */
    private Board board(boolean arduino) throws UsageException {
        Board b = board == null ? (arduino ? Board.UNO : Board.HOST) : Board.of(board);
        if (b == null) {
            throw new UsageException("--board must be uno, nano, esp32 or host, got '" + board + "'");
        }
        if (arduino && b == Board.HOST) {
            throw new UsageException("--board host is for --target c; an Arduino sketch runs on uno, nano or esp32");
        }
        if (!arduino && (!pins.isEmpty() || model != null || !servo.equals("pwm") || consoleSensors)) {
            throw new UsageException("--servo, --pins, --model and --console-sensors are for --target arduino");
        }
        return b;
    }

    /** Writes the runtime, the program and (for a sketch) the .ino into the folder, and says what it did. */
    private void write(Program program, CExport.Result result, SketchOptions sketch) throws IOException, UsageException {
        Map<String, String> files = new LinkedHashMap<>(CRuntime.runtime(sketch == null));
        files.putAll(result.files());
        Path dir = out;
        if (sketch != null) {
            String name = ArduinoSketch.sketchName(file);
            dir = out.resolve(name);
            files.put(name + ".ino", ArduinoSketch.ino(program, sketch, tick));
            files.put("parsl_servo.h", ServoTables.header(sketch));
        }
        ExportFiles.write(dir, files);
        PrintWriter o = spec.commandLine().getOut();
        o.println(result.memory().format());
        o.println("wrote " + files.size() + " files to " + dir);
        if (sketch == null) {
            o.println("build: cc -std=c99 -O2 -o program " + dir + "/*.c -lm");
        }
    }

    /** For messages: a diagnostic list as lines. */
    static String lines(List<Diagnostic> ds) {
        return String.join("\n", ds.stream().map(Diagnostic::format).toList());
    }
}
