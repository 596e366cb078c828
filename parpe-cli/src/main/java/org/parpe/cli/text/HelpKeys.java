package org.parpe.cli.text;

import java.util.List;

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

    /** The commands whose options and parameters are translated. */
    public static final List<String> OPTIONS_OF = List.of("check", "run");

    /** Every key of a help bundle. */
    public static final List<String> KEYS = keys();

    private HelpKeys() {
    }

    private static List<String> keys() {
        List<String> k = new java.util.ArrayList<>(List.of("usage.synopsisHeading", "usage.commandListHeading",
                "help", "version", "lang", "parpe.usage.description"));
        for (int i = 0; i <= 6; i++) {
            k.add("parpe.usage.footer." + i);
        }
        COMMANDS.forEach(c -> k.add("parpe." + c + ".usage.description"));
        k.add("parpe.check.files");
        for (String o : List.of("file", "duration", "tick", "param", "stimulus", "trace", "seed", "sim", "metrics",
                "world", "plot", "realtime", "port", "hardware", "diverge", "baud", "on-fault", "read-timeout", "retries")) {
            k.add("parpe.run." + o);
        }
        return List.copyOf(k);
    }
}
