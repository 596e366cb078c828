package org.parpe.cli.export;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.parpe.cli.options.ClockOptions;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.ParamValues;
import org.parpe.cli.options.UsageException;
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
 * board; {@code parpe export --target mjcf|urdf|sdf --robot ROBOT --out DIR [SCRIPT]}: the robot
 * for MuJoCo, ROS tools or Gazebo, with the script's gait ({@link RobotExport}). Exit codes as
 * {@code run}: 1 script or robot errors (also what the board cannot hold), 2 usage errors.
 */
@Command(name = "export", mixinStandardHelpOptions = true, description = "Compile a PARSL script to C99 or to an"
        + " Arduino sketch that runs it without a PC (see docs/embedded.md), or write a robot as MJCF, URDF or SDF"
        + " with a script's gait (see docs/bridges.md).")
public final class ExportCommand implements Callable<Integer> {
    @Parameters(index = "0", arity = "0..1", paramLabel = "SCRIPT",
            description = "The PARSL script (for mjcf, urdf and sdf: optional, its gait is exported with the robot).")
    Path file;

    @Option(names = "--target", paramLabel = "c|arduino|mjcf|urdf|sdf", defaultValue = "c",
            description = "c: runtime + tables + a host trace program; arduino: a sketch folder; mjcf, urdf, sdf: the"
                    + " robot of --robot for MuJoCo, ROS tools, Gazebo (default ${DEFAULT-VALUE}).")
    String target;

    @Option(names = "--robot", paramLabel = "ROBOT",
            description = "For mjcf, urdf, sdf: the robot, as --sim takes it (a configuration file or snake:n=12, centipede, ...).")
    String robot;

    @Option(names = "--duration", paramLabel = "SECONDS", defaultValue = "20",
            description = "For mjcf, urdf, sdf with a script: how long a run the gait holds (default ${DEFAULT-VALUE}).")
    double duration;

    @Option(names = "--stimulus", paramLabel = "FILE", description = "For mjcf, urdf, sdf with a script: timed control and sensor assignments.")
    Path stimulus;

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
        if (List.of("mjcf", "urdf", "sdf").contains(target)) {
            return exportRobot(err);
        }
        boolean arduino = switch (target) {
            case "c" -> false;
            case "arduino" -> true;
            default -> throw new UsageException("--target must be c, arduino, mjcf, urdf or sdf, got '" + target + "'");
        };
        if (file == null) {
            throw new UsageException("--target " + target + " exports a script: give the SCRIPT");
        }
        if (robot != null || stimulus != null) {
            throw new UsageException("--robot and --stimulus are for --target mjcf, urdf and sdf");
        }
        Inputs.check(file);
        Board b = board(arduino);
        if (arduino) {
            ArduinoSketch.tickMicros(tick);
        }
        SketchOptions sketch = arduino ? SketchOptions.of(servo, pins, baud, model, consoleSensors) : null;
        LoadResult r = ScriptLoader.load(file, ParamValues.parse(params));
        int refused = org.parpe.cli.terminal.LoadReport.exitCode(r, err::println);
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

    /** MJCF, URDF or SDF of {@code --robot}, with the gait of the script if one is given. */
    private int exportRobot(PrintWriter err) throws UsageException, IOException {
        if (robot == null) {
            throw new UsageException("--target " + target + " needs --robot: a configuration file or a generator"
                    + " (snake:n=12, centipede, wheel, loop, humanoid)");
        }
        if (board != null || !pins.isEmpty() || model != null || !servo.equals("pwm") || consoleSensors) {
            throw new UsageException("--board, --servo, --pins, --model and --console-sensors are for --target c and arduino");
        }
        if (!(duration > 0) || !Double.isFinite(duration)) {
            throw new UsageException("--duration must be a number of seconds > 0, got " + duration);
        }
        Program program = null;
        List<org.parpe.core.run.Stimulus> stimuli = List.of();
        if (file != null) {
            Inputs.check(file);
            LoadResult r = ScriptLoader.load(file, ParamValues.parse(params));
            int refused = org.parpe.cli.terminal.LoadReport.exitCode(r, err::println);
            if (refused != 0) {
                return refused;
            }
            program = r.program();
            if (stimulus != null) {
                Inputs.check(stimulus);
            }
            stimuli = Inputs.stimuli(stimulus, program);
        } else if (stimulus != null || !params.isEmpty()) {
            throw new UsageException("--stimulus and --param need a SCRIPT whose gait is exported");
        }
        return RobotExport.run(new RobotExport.Request(target, robot, program, stimuli, duration, tick, out),
                spec.commandLine().getOut(), err);
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
