package org.parpe.gui.automation;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.parpe.cli.text.CommandLanguage;
import org.parpe.cli.text.ParseErrors;
import org.parpe.gui.text.UiMsg;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * What {@code parpe gui} was asked to do, parsed by picocli as the command line's commands are, and
 * in their language: picocli's errors by the command line's {@link ParseErrors}, the help from the
 * bundle {@link #HELP} (the translations of the annotations below).
 *
 * @param file       the script to open, or {@code null}
 * @param runFor     seconds of simulated time to run the script for, or a negative number for no run
 * @param screenshot where to save a picture of the window, or {@code null}
 * @param exit       whether to close the IDE when the automation is done
 * @param bench      whether to print start-up and drawing figures and exit
 * @param posePanel  whether to bring the Pose panel to the front with the poses the script plays
 * @param grid       the gait table to show in the grid editor (selected whole), or {@code null}
 * @param help       whether {@code --help} was asked for (nothing else is done then)
 */
public record LaunchOptions(Path file, double runFor, Path screenshot, boolean exit, boolean bench,
                            boolean posePanel, String grid, boolean help) {

    /**
     * The bundle of the help texts in German, Spanish and Japanese (English is in the annotations),
     * keyed as picocli looks them up: {@code usage.synopsisHeading}, {@code usage.description} and
     * each option's long name without dashes ({@link #helpKeys}).
     */
    public static final String HELP = "org.parpe.gui.text.LaunchHelp";

    /** The options as picocli fills them in; {@link #parse} turns them into a record. */
    @Command(name = "parpe gui", description = "Open the PARPE IDE, optionally on a script; the options automate it"
            + " for documentation and tests.", sortOptions = false)
    private static final class Arguments {
        // all of them, so that a second one gets a message that says so; shown as the one it may be
        @Parameters(arity = "0..*", paramLabel = "[FILE]", hideParamSyntax = true, descriptionKey = "files",
                description = "PARSL script to open")
        List<Path> files = new ArrayList<>();

        @Option(names = "--run-for", paramLabel = "S",
                description = "run the script in the simulator for S seconds of simulated time")
        String runFor;

        @Option(names = "--screenshot", paramLabel = "F", description = "save a PNG picture of the window (after the run, if any)")
        Path screenshot;

        @Option(names = "--exit", description = "close the IDE when done")
        boolean exit;

        @Option(names = "--pose-panel",
                description = "show the Pose panel with the poses of the gait table the script plays (a recording)")
        boolean posePanel;

        @Option(names = "--grid", paramLabel = "NAME", description = "show gait table NAME in the grid editor, all of it selected")
        String grid;

        @Option(names = "--bench", description = "print window-up time, 3D frame rate (centipede), the live diagrams during a run"
                + " and opening a 10 MB script as name=value lines, then exit")
        boolean bench;

        // read before the others by langOption, so that their errors are in its language; here for the help
        @Option(names = "--lang", paramLabel = "CODE", description = "language of the IDE: en, de, es or ja (default: the"
                + " Language preference, else LC_ALL, LC_MESSAGES or LANG)")
        String lang;

        @Option(names = {"-h", "--help"}, usageHelp = true, description = "show this help and exit")
        boolean help;
    }

    /**
     * The usage text printed for {@code --help} and bad arguments, in the chosen language
     * ({@link org.parpe.core.text.Lang#current()}).
     */
    public static String usage() {
        return commandLine().getUsageMessage().stripTrailing();
    }

    /**
     * The language {@code --lang} names among {@code args}, read before the options are parsed (so
     * that their errors are told in it), as the command line reads it; null without one.
     */
    public static String langOption(List<String> args) {
        return CommandLanguage.langOption(args.toArray(new String[0]));
    }

    /** Picocli's command line of the options, its help in the chosen language. */
    private static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new Arguments());
        CommandLanguage.helpIn(cl, HELP);
        return cl;
    }

    /** The keys a help bundle ({@link #HELP}) has: the heading, the description, each option's and parameter's. */
    static List<String> helpKeys() {
        List<String> keys = new ArrayList<>(List.of("usage.synopsisHeading", "usage.description"));
        for (CommandLine.Model.ArgSpec a : new CommandLine(new Arguments()).getCommandSpec().args()) {
            keys.add(a.descriptionKey().isEmpty() ? ((CommandLine.Model.OptionSpec) a).longestName().replaceFirst("^-+", "")
                    : a.descriptionKey());
        }
        return keys;
    }

    /** Whether anything automatic is requested. */
    public boolean automated() {
        return runFor >= 0 || screenshot != null || exit || posePanel || grid != null;
    }

    /**
     * Parses the arguments that follow {@code gui}; {@code --lang} is read by {@link #langOption}.
     *
     * @throws IllegalArgumentException with a message for the user on a bad argument, in the chosen language
     */
    public static LaunchOptions parse(List<String> args) {
        Arguments a = new Arguments();
        try {
            new CommandLine(a).parseArgs(args.toArray(new String[0]));
        } catch (CommandLine.ParameterException e) {
            throw new IllegalArgumentException(ParseErrors.of(e).toString(), e);
        }
        if (a.files.size() > 1) {
            throw new IllegalArgumentException(UiMsg.ONLY_ONE_FILE.text(a.files.get(0), a.files.get(1)));
        }
        return new LaunchOptions(a.files.isEmpty() ? null : a.files.get(0), a.runFor == null ? -1 : seconds(a.runFor),
                a.screenshot, a.exit, a.bench, a.posePanel, a.grid, a.help);
    }

    private static double seconds(String text) {
        try {
            double v = Double.parseDouble(text);
            if (!Double.isFinite(v) || v < 0) {
                throw new NumberFormatException();
            }
            return v;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(UiMsg.RUN_FOR_SECONDS.text(text));
        }
    }
}
