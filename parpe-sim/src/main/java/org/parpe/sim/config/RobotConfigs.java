package org.parpe.sim.config;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Names;

/**
 * Where simulated robots come from: a standard configuration made by a generator
 * ({@code snake}, {@code loop}, {@code wheel}, {@code centipede}, {@code humanoid}, with
 * {@code :key=value,...} arguments) or a configuration file. Used by the CLI's {@code --sim}
 * and by the IDE.
 */
public final class RobotConfigs {
    private static final List<String> GENERATORS = List.of("snake", "loop", "wheel", "centipede", "humanoid");
    /** Most modules a generated chain may have. */
    private static final int MAX_MODULES = 1000;

    private RobotConfigs() {
    }

    /** The generator names, in documentation order. */
    public static List<String> generatorNames() {
        return GENERATORS;
    }

    /**
     * The configuration named by {@code specOrPath}: {@code GENERATOR[:key=value,...]} or a path
     * to a configuration file (anything ending in {@code .xml} or naming an existing file).
     * {@code moduleIds} are the script's modules (may be empty): generators size themselves from
     * them where a size is not given. Returns {@code null} after reporting errors to {@code diags}.
     * The configuration is not assembled here (this package knows nothing of the physics):
     * {@link org.parpe.sim.SimTarget#blueprint} assembles it once and reports what does not fit
     * together (a loop that does not close, two parts on one plate), and a
     * {@link org.parpe.sim.Simulator} made directly from it refuses such a configuration.
     */
    public static RobotConfig resolve(String specOrPath, int[] moduleIds, DiagnosticSink diags) {
        String spec = specOrPath.trim();
        RobotConfig config;
        if (isFile(spec)) {
            config = ConfigReader.read(Path.of(spec), diags);
        } else {
            config = generate(spec, moduleIds, diags);
        }
        return config;
    }

    /**
     * Reads the configuration file text {@code text} (of {@code file}, the name used in
     * messages), as {@link #resolve} reads a file, problems to {@code diags}; a text that defines
     * no part yet is no problem here (its configuration is null), so a builder can start from it.
     */
    public static ConfigFile read(String file, String text, DiagnosticSink diags) {
        return ConfigReader.read(file, text, diags);
    }

    /** Whether {@code specOrPath} names a configuration file (not a generator), as {@link #resolve} takes it. */
    public static boolean isFile(String specOrPath) {
        String spec = specOrPath.trim();
        return spec.endsWith(".xml") || spec.contains("/") || Files.isRegularFile(Path.of(spec));
    }

    private static RobotConfig generate(String spec, int[] moduleIds, DiagnosticSink diags) {
        int colon = spec.indexOf(':');
        String name = colon < 0 ? spec : spec.substring(0, colon);
        GeneratorArgs args = colon < 0 ? GeneratorArgs.empty("--sim " + spec, diags)
                : GeneratorArgs.parse("--sim " + spec, spec.substring(colon + 1), colon + 2, diags);
        int fromScript = moduleIds.length == 0 ? 0 : moduleIds[moduleIds.length - 1] + 1;
        RobotConfig config = switch (name) {
            case "snake" -> Generators.snake(spec, args.integer("n", Math.max(2, fromScript), 1, MAX_MODULES),
                    args.word("axes", "parallel", "alternate").equals("alternate"));
            case "loop" -> Generators.loop(spec, args.integer("n", Math.max(6, fromScript), 4, 72));
            case "wheel" -> Generators.wheel(spec, args.integer("n", fromScript >= 3 ? Math.min(fromScript, 16) : 8, 3, 16));
            case "centipede" -> Generators.centipede(spec, args.integer("pairs", 7, 1, 40), args.integer("leg", 2, 1, 4),
                    args.integer("between", 4, 0, 20), args.integer("head", 2, 0, 20), args.integer("tail", 1, 0, 20));
            case "humanoid" -> Generators.humanoid(spec);
            default -> null;
        };
        if (config == null) {
            diags.error(new SourcePos("--sim " + spec, 1, 1), org.parpe.core.text.Msg.UNKNOWN_ROBOT, name,
                    String.join(", ", GENERATORS), Names.suggest(name, GENERATORS));
            return null;
        }
        return args.finish(name) ? config : null;
    }

    /**
     * Warns about script modules the robot does not have (their commands are ignored); returns
     * how many there were.
     */
    public static int checkModules(RobotConfig config, int[] moduleIds, DiagnosticSink diags) {
        int[] have = config.moduleIds();
        int missing = 0;
        StringBuilder list = new StringBuilder();
        for (int id : moduleIds) {
            if (java.util.Arrays.binarySearch(have, id) < 0) {
                list.append(missing++ == 0 ? "" : ", ").append(id);
            }
        }
        if (missing > 0) {
            diags.warning(SourcePos.origin("simulated robot " + config.name()), org.parpe.core.text.Msg.ROBOT_LACKS_MODULES,
                    list, have.length);
        }
        return missing;
    }
}
