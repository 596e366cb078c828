package org.parpe.cli.text;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The keys of the help bundles ({@code Help_de.properties} etc.), as picocli looks them up: a
 * heading or an option shared by every command (unqualified), a command's description and
 * footer ({@code parpe.COMMAND.usage.description}) and a command's options and parameters
 * ({@code parpe.COMMAND.OPTION}, the option's long name without dashes, or its
 * {@code descriptionKey}). {@code CliTextTest} checks that each translation has exactly these
 * and that each names a command or option that exists. What is not here is shown in English.
 */
public final class HelpKeys {
    /** The commands whose descriptions the command list of {@code parpe --help} shows. */
    public static final List<String> COMMANDS = List.of("check", "run", "bench", "race", "robot", "grade", "sweep",
            "optimize", "merge", "emulate", "record", "scan", "calibrate", "export", "diagram", "help");

    /** The commands whose options and parameters are translated, each with the keys of its options. */
    private static final Map<String, List<String>> OPTIONS = options();

    /** The commands whose options and parameters are translated. */
    public static final List<String> OPTIONS_OF = List.copyOf(OPTIONS.keySet());

    /** Every key of a help bundle. */
    public static final List<String> KEYS = keys();

    private HelpKeys() {
    }

    private static List<String> keys() {
        List<String> k = new ArrayList<>(List.of("usage.synopsisHeading", "usage.commandListHeading",
                "help", "version", "lang", "parpe.usage.description"));
        for (int i = 0; i <= 6; i++) {
            k.add("parpe.usage.footer." + i);
        }
        COMMANDS.forEach(c -> k.add("parpe." + c + ".usage.description"));
        OPTIONS.forEach((c, options) -> options.forEach(o -> k.add("parpe." + c + "." + o)));
        return List.copyOf(k);
    }

    private static Map<String, List<String>> options() {
        Map<String, List<String>> o = new LinkedHashMap<>();
        o.put("check", List.of("files"));
        o.put("run", List.of("file", "duration", "tick", "param", "stimulus", "trace", "seed", "sim", "metrics",
                "world", "plot", "realtime", "port", "hardware", "diverge", "baud", "on-fault", "read-timeout", "retries"));
        o.put("race", List.of("files", "sim", "duration", "world", "tick"));
        o.put("robot", List.of("robot", "check", "kit", "out"));
        o.put("diagram", List.of("file", "view", "behavior", "automaton", "instance", "duration", "tick", "param", "out",
                "width"));
        List<String> simSweep = List.of("file", "sim", "duration", "tick", "param", "jobs", "seed", "world", "fall-tilt");
        List<String> sweep = new ArrayList<>(List.of("vary", "random", "repeat", "out", "plot", "objective", "count-fallen",
                "shard"));
        sweep.addAll(simSweep);
        o.put("sweep", sweep);
        List<String> optimize = new ArrayList<>(List.of("objective", "budget", "starts", "max-tilt", "not-fallen", "out",
                "force", "plot"));
        optimize.addAll(simSweep);
        o.put("optimize", optimize);
        o.put("merge", List.of("files", "out", "plot", "objective", "count-fallen"));
        o.put("grade", List.of("challenge", "students", "out", "jobs", "cpu-limit", "memory", "shard", "merge"));
        o.put("bench", List.of("only", "list", "no-fork", "save", "compare"));
        o.put("emulate", List.of("port", "modules", "baud", "protocol", "model", "drop", "corrupt", "latency", "unplug-after",
                "unplug-for", "speed", "seed", "log", "duration"));
        o.put("record", List.of("port", "hardware", "baud", "group", "script", "modules", "out", "every", "count"));
        o.put("scan", List.of("port", "protocol", "baud", "ids", "out", "force"));
        o.put("calibrate", List.of("hardware", "port"));
        o.put("export", List.of("file", "target", "robot", "duration", "stimulus", "out", "tick", "param", "board", "servo",
                "pins", "baud", "model", "console-sensors"));
        return o;
    }
}
