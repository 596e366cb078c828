package org.parpe.cli.export;

import org.parpe.cli.text.CliMsg;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.parpe.cli.options.ClockOptions;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.ParamValues;
import org.parpe.cli.options.UsageException;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.export.Board;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.serial.export.ProgramExport;
import org.parpe.serial.export.SketchOptions;
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
    @Parameters(index = "0", arity = "0..1", paramLabel = "SCRIPT", descriptionKey = "file",
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
            err.println("parpe: " + CliMsg.CANNOT_WRITE.text(out, e.getMessage()));
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
            default -> throw new UsageException(CliMsg.BAD_TARGET.text(target));
        };
        if (file == null) {
            throw new UsageException(CliMsg.TARGET_NEEDS_SCRIPT.text(target));
        }
        if (robot != null || stimulus != null) {
            throw new UsageException(CliMsg.ROBOT_OPTIONS_ONLY.text());
        }
        Inputs.check(file);
        ProgramExport.Request request = request(arduino);
        LoadResult r = ScriptLoader.load(file, ParamValues.parse(params));
        int refused = org.parpe.cli.terminal.LoadReport.exitCode(r, err::println);
        if (refused != 0) {
            return refused;
        }
        DiagnosticList diags = new DiagnosticList();
        ProgramExport.Result result = ProgramExport.export(r.program(), request, diags);
        diags.all().forEach(d -> err.println(d.format()));
        if (result == null) {
            return 1;
        }
        Path dir = result.dir(out);
        ExportFiles.write(dir, result.files());
        PrintWriter o = spec.commandLine().getOut();
        o.println(result.memory().format());
        o.println(CliMsg.WROTE_FILES.text(result.files().size(), dir));
        if (!arduino) {
            o.println(CliMsg.BUILD_WITH.text("cc -std=c99 -O2 -o program " + dir + "/*.c -lm"));
        }
        return 0;
    }

    /** MJCF, URDF or SDF of {@code --robot}, with the gait of the script if one is given. */
    private int exportRobot(PrintWriter err) throws UsageException, IOException {
        if (robot == null) {
            throw new UsageException(CliMsg.TARGET_NEEDS_ROBOT.text(target));
        }
        if (board != null || !pins.isEmpty() || model != null || !servo.equals("pwm") || consoleSensors) {
            throw new UsageException(CliMsg.BOARD_OPTIONS_ONLY.text());
        }
        if (!(duration > 0) || !Double.isFinite(duration)) {
            throw new UsageException(CliMsg.EXPORT_DURATION.text(duration));
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
            throw new UsageException(CliMsg.GAIT_NEEDS_SCRIPT.text());
        }
        return RobotExport.run(new RobotExport.Request(target, robot, program, stimuli, duration, tick, out),
                spec.commandLine().getOut(), err);
    }


    /** The export's choices from the options: {@code --board} checked against the target, the sketch's servo driver. */
    private ProgramExport.Request request(boolean arduino) throws UsageException {
        ProgramExport.Target t = arduino ? ProgramExport.Target.ARDUINO : ProgramExport.Target.C;
        Board b = board == null ? t.defaultBoard() : Board.of(board);
        if (b == null) {
            throw new UsageException(CliMsg.BAD_BOARD.text(board));
        }
        if (!arduino && (!pins.isEmpty() || model != null || !servo.equals("pwm") || consoleSensors)) {
            throw new UsageException(org.parpe.core.text.Msg.SKETCH_OPTIONS_ONLY.text());
        }
        try {
            SketchOptions sketch = arduino ? SketchOptions.of(servo, pins, baud, model, consoleSensors) : null;
            return new ProgramExport.Request(t, b, tick, sketch);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
    }

    /** For messages: a diagnostic list as lines. */
    static String lines(List<Diagnostic> ds) {
        return String.join("\n", ds.stream().map(Diagnostic::format).toList());
    }
}
