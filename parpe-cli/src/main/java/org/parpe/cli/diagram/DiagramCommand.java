package org.parpe.cli.diagram;

import org.parpe.cli.text.CliMsg;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import javax.imageio.ImageIO;
import org.parpe.cli.options.ClockOptions;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.terminal.LoadReport;
import org.parpe.cli.options.OutputFile;
import org.parpe.cli.options.ParamValues;
import org.parpe.cli.options.UsageException;
import org.parpe.core.diagram.Diagrams;
import org.parpe.core.diagram.Gait;
import org.parpe.core.diagram.Layouts;
import org.parpe.core.diagram.Scene;
import org.parpe.core.expr.Names;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Group;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Program;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.ScriptRuntimeError;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code parpe diagram SCRIPT --out FILE.svg|.png}: draws one view of a script (the
 * {@code <main>} lane, a behavior's swimlanes, an automaton's ring, an instance's phase wheel or
 * the gait diagram) for worksheets, documents and tests.
 */
@Command(name = "diagram", mixinStandardHelpOptions = true, description = "Draw a diagram of a PARSL script:"
        + " the <main> program lane, a behavior's swimlanes, an automaton ring, a phase wheel or the gait diagram,"
        + " as SVG or PNG (by the --out file's extension).")
public final class DiagramCommand implements Callable<Integer> {
    /** The most ticks a gait diagram records: far more than its width in pixels. */
    static final int MAX_GAIT_TICKS = 100_000;

    /** The views. */
    enum View { program, lanes, ring, phase, gait }

    @Parameters(index = "0", paramLabel = "SCRIPT", descriptionKey = "file", description = "The PARSL script.")
    Path file;

    @Option(names = "--view", paramLabel = "VIEW", defaultValue = "program",
            description = "program, lanes, ring, phase or gait (default: ${DEFAULT-VALUE}).")
    View view;

    @Option(names = "--behavior", paramLabel = "B", description = "The behavior of lanes and phase (default: the first"
            + " <main> entry's, else the first behavior).")
    String behavior;

    @Option(names = "--automaton", paramLabel = "A", description = "The automaton of ring (default: the first one).")
    String automaton;

    @Option(names = "--instance", paramLabel = "N", defaultValue = "0",
            description = "For phase: the behavior's instance, 0 for the first (default: ${DEFAULT-VALUE}).")
    int instance;

    @Option(names = "--duration", paramLabel = "S", defaultValue = "6",
            description = "For gait: seconds to run (default: ${DEFAULT-VALUE}).")
    double duration;

    @Option(names = "--tick", paramLabel = "S", defaultValue = "0.01", description = "For gait: the tick (default: ${DEFAULT-VALUE}).")
    double tick;

    @Option(names = "--param", paramLabel = "NAME=VALUE", description = "Set a parameter (repeatable).")
    List<String> params = new ArrayList<>();

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "The picture: FILE.svg or FILE.png.")
    String out;

    @Option(names = "--width", paramLabel = "PIXELS", description = "For a .png: its width, within [" + ScenePng.MIN_SIDE
            + ", " + ScenePng.MAX_WIDTH + "]; the height follows (default: the diagram's own size; an SVG scales by itself).")
    Integer width;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        return execute(spec.commandLine().getErr());
    }

    private int execute(PrintWriter err) throws Exception {
        String lower = out.toLowerCase(Locale.ROOT);
        boolean png = lower.endsWith(".png");
        if (!png && !lower.endsWith(".svg")) {
            throw new UsageException(CliMsg.OUT_SVG_OR_PNG.text(out));
        }
        if (width != null && !png) {
            throw new UsageException(CliMsg.WIDTH_FOR_PNG.text());
        }
        if (width != null && (width < ScenePng.MIN_SIDE || width > ScenePng.MAX_WIDTH)) {
            throw new UsageException(CliMsg.WIDTH_RANGE.text(ScenePng.MIN_SIDE, ScenePng.MAX_WIDTH, width));
        }
        if (view == View.gait) {
            ClockOptions.check(tick, duration);
            if (duration / tick > MAX_GAIT_TICKS) {
                throw new UsageException(CliMsg.GAIT_TOO_LONG.text(duration, tick, MAX_GAIT_TICKS));
            }
        }
        Inputs.check(file);
        LoadResult r = ScriptLoader.load(file, ParamValues.parse(params));
        int refused = LoadReport.exitCode(r, err::println);
        if (refused != 0) {
            return refused;
        }
        OutputFile target = OutputFile.of(OutputFile.plan(r.files()), "--out", out);
        Scene scene;
        try {
            scene = scene(r.program());
        } catch (ScriptRuntimeError e) {
            err.println(e.diagnostic().format());
            return 3;
        }
        if (png) {
            int w = width == null ? scene.width() : width;
            String tooLarge = ScenePng.tooLarge(scene, w);
            if (tooLarge != null) {
                throw new UsageException((width == null ? CliMsg.CANNOT_DRAW_DIAGRAM
                        : CliMsg.CANNOT_DRAW_DIAGRAM_WIDTH).text(view, out, tooLarge));
            }
            target.write(o -> ImageIO.write(ScenePng.draw(scene, w), "png", o));
        } else {
            target.write(scene.svg());
        }
        return 0;
    }

    /** The scene of the chosen view. */
    Scene scene(Program p) throws UsageException {
        switch (view) {
            case program:
                return Layouts.program(Diagrams.program(p).orElseThrow(
                        () -> new UsageException(CliMsg.DIAGRAM_NO_MAIN.text(file))));
            case lanes:
                return Layouts.lanes(Diagrams.swimlanes(p, behavior(p)));
            case ring:
                return Layouts.ring(Diagrams.ring(p, automaton(p)));
            case phase:
                return phase(p);
            default:
                return Layouts.gait(Gait.record(p, new RunOptions(tick, 0, List.of()), duration));
        }
    }

    private Behavior behavior(Program p) throws UsageException {
        if (behavior != null) {
            return p.behavior(behavior).orElseThrow(() -> new UsageException(CliMsg.NO_SUCH_BEHAVIOR.text(behavior, file,
                    Names.suggest(behavior, p.behaviors().stream().map(Behavior::name).toList()))));
        }
        if (p.main() != null && !p.main().entries().isEmpty()) {
            return p.main().entries().get(0).definition();
        }
        if (p.behaviors().isEmpty()) {
            throw new UsageException(CliMsg.NO_BEHAVIORS.text(file));
        }
        return p.behaviors().get(0);
    }

    private org.parpe.core.model.Automaton automaton(Program p) throws UsageException {
        if (automaton != null) {
            return p.automaton(automaton).orElseThrow(() -> new UsageException(CliMsg.NO_SUCH_AUTOMATON.text(automaton, file,
                    Names.suggest(automaton, p.automata().stream().map(a -> a.name()).toList()))));
        }
        if (p.automata().isEmpty()) {
            throw new UsageException(CliMsg.NO_AUTOMATA.text(file));
        }
        return p.automata().get(0);
    }

    private Scene phase(Program p) throws UsageException {
        Behavior b = behavior(p);
        List<Instance> all = b.instances();
        if (instance < 0 || instance >= all.size()) {
            throw new UsageException(CliMsg.INSTANCE_RANGE.text(all.size() - 1, b.name(), instance));
        }
        Instance i = all.get(instance);
        Group g = Diagrams.groupOf(p, b, i).orElseThrow(() -> new UsageException(CliMsg.GROUP_IS_MACRO.text(instance,
                b.name(), i.groupRef().name())));
        return Layouts.wheel(Diagrams.wheel(i, g));
    }
}
