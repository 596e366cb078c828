package org.parpe.cli.sim;

import org.parpe.cli.text.CliMsg;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import javax.imageio.ImageIO;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.OutputFile;
import org.parpe.cli.options.UsageException;
import org.parpe.cli.diagram.ScenePng;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diagram.Scene;
import org.parpe.sim.config.Kit;
import org.parpe.sim.config.PartType;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;
import org.parpe.sim.internal.Assembly;
import org.parpe.sim.sheet.RobotSheet;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code parpe robot CONFIG [--check] [--kit KIT] [--out FILE.svg|.png]}: reads and assembles a
 * robot as {@code --sim} does, reports every problem located (and every part type beyond the
 * kit), and draws the robot for a worksheet. Exit codes: 0 fine, 1 problems of the robot or
 * the kit, 2 usage errors.
 */
@Command(name = "robot", mixinStandardHelpOptions = true, description = "Check a robot configuration (every problem as"
        + " FILE:LINE:COL), against a class's kit with --kit, and draw it for a worksheet (top, front and side views"
        + " and a parts list) with --out.")
public final class RobotCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "CONFIG", descriptionKey = "robot", description = "The robot, as --sim takes it: a configuration file"
            + " CONFIG.xml or a generator such as snake:n=12, centipede, wheel, loop, humanoid.")
    String robot;

    @Option(names = "--check", description = "Only check (the default without --out).")
    boolean check;

    @Option(names = "--kit", paramLabel = "KIT.xml", description = "Also check that the robot can be built from this kit.")
    Path kit;

    @Option(names = "--out", paramLabel = "FILE", description = "Draw the robot: FILE.svg or FILE.png.")
    String out;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        String lower = out == null ? "" : out.toLowerCase(Locale.ROOT);
        if (out != null && !lower.endsWith(".png") && !lower.endsWith(".svg")) {
            throw new UsageException(CliMsg.OUT_SVG_OR_PNG.text(out));
        }
        if (check && out != null) {
            throw new UsageException(CliMsg.CHECK_ONLY.text());
        }
        List<Path> inputs = new ArrayList<>();
        if (kit != null) {
            Inputs.check(kit);
            inputs.add(kit);
        }
        if (RobotConfigs.isFile(robot)) {
            Path config = Path.of(robot.trim());
            Inputs.check(config);
            inputs.add(config);
        }
        OutputFile target = out == null ? null : OutputFile.of(OutputFile.plan(inputs), "--out", out);
        DiagnosticList diags = new DiagnosticList();
        Kit k = kit == null ? null : Kit.read(kit, diags);
        RobotConfig c = RobotConfigs.resolve(robot, new int[0], diags);
        Assembly a = c == null ? null : Assembly.build(c, diags);
        if (c != null && k != null) {
            k.check(c, diags);
        }
        diags.all().forEach(d -> err.println(d.format()));
        if (diags.hasErrors()) {
            err.println(robot + ": " + (diags.errorCount() == 1 ? CliMsg.ONE_ERROR : CliMsg.N_ERRORS).text(diags.errorCount()));
            return 1;
        }
        if (target == null) {
            spec.commandLine().getOut().println(robot + ": " + (k == null ? CliMsg.ROBOT_OK.text(RobotSheet.summary(c.parts()))
                    : CliMsg.ROBOT_OK_KIT.text(RobotSheet.summary(c.parts()), left(k.left(c)))));
            return 0;
        }
        Scene scene = RobotSheet.of(c, a);
        if (lower.endsWith(".png")) {
            String tooLarge = ScenePng.tooLarge(scene, scene.width());
            if (tooLarge != null) {
                throw new UsageException(CliMsg.CANNOT_DRAW_ROBOT.text(out, tooLarge));
            }
            target.write(o -> ImageIO.write(ScenePng.draw(scene, scene.width()), "png", o));
        } else {
            target.write(scene.svg());
        }
        spec.commandLine().getOut().println(CliMsg.WROTE.text(out));
        return 0;
    }

    /** "4 segments, 0 nodes, 2 feet, 1 hub". */
    private static String left(Map<PartType, Integer> left) {
        return String.join(", ", left.entrySet().stream().map(e -> e.getKey().count(e.getValue()).toString()).toList());
    }
}
