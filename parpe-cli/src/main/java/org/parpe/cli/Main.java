package org.parpe.cli;

import java.io.InputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.function.UnaryOperator;
import org.parpe.cli.bench.BenchCommand;
import org.parpe.cli.text.CliMsg;
import org.parpe.cli.text.CommandLanguage;
import org.parpe.cli.text.ParseErrors;
import org.parpe.cli.options.ReadsInput;
import org.parpe.cli.options.UsageException;
import org.parpe.cli.terminal.ExitCode;
import org.parpe.core.expr.Names;
import org.parpe.core.io.CrashReport;
import org.parpe.core.text.Lang;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** The {@code parpe} command line: checks and runs PARSL scripts headless. */
@Command(name = "parpe", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = "PolyKinetic Phase Automata Robot Programming Environment: check and run PARSL scripts.",
        subcommands = {
            CheckCommand.class,
            RunCommand.class,
            BenchCommand.class,
            org.parpe.cli.sim.RaceCommand.class,
            org.parpe.cli.sim.RobotCommand.class,
            org.parpe.cli.grade.GradeCommand.class,
            org.parpe.cli.sweep.SweepCommand.class,
            org.parpe.cli.sweep.OptimizeCommand.class,
            org.parpe.cli.sweep.MergeCommand.class,
            org.parpe.cli.hw.EmulateCommand.class,
            org.parpe.cli.hw.RecordCommand.class,
            org.parpe.cli.hw.ScanCommand.class,
            org.parpe.cli.hw.CalibrateCommand.class,
            org.parpe.cli.export.ExportCommand.class,
            org.parpe.cli.diagram.DiagramCommand.class,
            CommandLine.HelpCommand.class
        },
        footer = {"", "  gui [FILE] [--run-for S] [--screenshot F.png] [--exit]",
                  "          Open the IDE (parpe with no arguments, or with just a .xml or .parsl",
                  "          file, does the same).",
                  "", "Exit codes: 0 success, 1 script errors, 2 usage errors, 3 run-time error,",
                  "            4 internal error."})
public final class Main implements Runnable {
    /** The encoding of the streams picocli writes to: the JVM's, or UTF-8 after {@link #utf8Terminal}. */
    private static java.nio.charset.Charset terminal = java.nio.charset.Charset.defaultCharset();

    /** The bundle of the help texts in German, Spanish and Japanese (English is in the annotations). */
    public static final String HELP = "org.parpe.cli.text.Help";

    /** Every command takes it: picocli lists it; {@link #execute} has read it before picocli parses. */
    @Option(names = "--lang", paramLabel = "CODE", scope = CommandLine.ScopeType.INHERIT,
            description = "Language of messages and help: en, de, es or ja (default: from LC_ALL, LC_MESSAGES or LANG;"
                    + " English if none names one of them).")
    String lang;

    static {
        // Plots are drawn with AWT into images; the command line never opens a window, so AWT
        // must not load its X11 toolkit even where a display is set (and X libraries are absent).
        System.setProperty("java.awt.headless", "true");
    }

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }

    /** Runs the command line and exits with its code. */
    public static void main(String[] args) {
        utf8Terminal(System::getenv);
        System.exit(execute(args, System.out, System.err));
    }

    /** Standard output and error in UTF-8 where the locale names it ({@link org.parpe.core.text.Terminal}). */
    static void utf8Terminal(UnaryOperator<String> env) {
        terminal = org.parpe.core.text.Terminal.utf8WhereNamed(env);
    }

    /** {@code --version}: PARPE's version from the build. */
    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] {"PARPE " + org.parpe.core.Version.NUMBER};
        }
    }

    /** Runs the command line with the given streams; returns the exit code. */
    public static int execute(String[] args, PrintStream out, PrintStream err) {
        return execute(args, System.in, out, err, System::getenv);
    }

    /** Runs the command line with the given streams in the language the environment {@code env} chooses. */
    public static int execute(String[] args, PrintStream out, PrintStream err, UnaryOperator<String> env) {
        return execute(args, System.in, out, err, env);
    }

    /**
     * Runs the command line with the given streams in the language that {@code --lang} or the
     * environment {@code env} chooses ({@link Lang}); returns the exit code. The language is the
     * process's until the command ends. Commands that read input ({@link ReadsInput}) read {@code in}.
     */
    public static int execute(String[] args, InputStream in, PrintStream out, PrintStream err,
                              UnaryOperator<String> env) {
        // Without the IDE (the command-line jar alone), `parpe` with no arguments prints the usage.
        if (Ide.wanted(args) && (args.length > 0 || Ide.present())) {
            return Ide.open(args, err);
        }
        Locale before = Lang.current();
        try {
            Lang.use(Lang.fromEnvironment(env));
            String code = CommandLanguage.langOption(args);
            if (code != null) {
                Locale chosen = Lang.parse(code);
                if (chosen == null) {
                    err.println("parpe: " + CliMsg.UNKNOWN_LANGUAGE.text(code, Lang.codes()));
                    return 2;
                }
                Lang.use(chosen);
            }
            return executeIn(args, in, out, err);
        } finally {
            Lang.use(before);
        }
    }

    private static int executeIn(String[] args, InputStream in, PrintStream out, PrintStream err) {
        CommandLine cl = new CommandLine(new Main());
        for (CommandLine sub : cl.getSubcommands().values()) {
            if (sub.getCommand() instanceof ReadsInput reader) {
                reader.readFrom(in);
            }
        }
        // picocli's help is written in the annotations (English) and translated by Help_*.properties
        CommandLanguage.helpIn(cl, HELP);
        cl.setOut(new PrintWriter(out, true, terminal));
        cl.setErr(new PrintWriter(err, true, terminal));
        cl.setExecutionExceptionHandler(Main::failed);
        cl.setExecutionStrategy(Main::executeMatched);
        cl.setParameterExceptionHandler((ex, args2) -> {
            String command = unknownCommand(ex, cl);
            if (command != null) {
                err.println("parpe: " + CliMsg.UNKNOWN_COMMAND.text(command, Names.suggest(command, cl.getSubcommands().keySet()),
                        String.join(", ", cl.getSubcommands().keySet())));
            } else {
                err.println("parpe: " + ParseErrors.of(ex));
                ParseErrors.printSuggestions(ex, err);
            }
            err.println(CliMsg.TRY_HELP.text(ex.getCommandLine() == cl ? "" : ex.getCommandLine().getCommandName() + " "));
            return 2;
        });
        try {
            return cl.execute(args);
        } catch (OutOfMemoryError e) {
            // inputs are capped at 16 MiB, which loads in well under 1 GiB; a smaller heap may not do
            err.println("parpe: " + CliMsg.OUT_OF_MEMORY.text(Runtime.getRuntime().maxMemory() >> 20));
            return ExitCode.INTERNAL_ERROR;
        }
    }

    /**
     * Runs the command the arguments name, once every argument was matched. Picocli does not
     * check for unmatched arguments when {@code --help} is among them, so {@code parpe NOSUCH
     * --help} would print the general help and exit 0; here it is the usage error it is.
     */
    private static int executeMatched(CommandLine.ParseResult parsed) {
        for (CommandLine.ParseResult p = parsed; p != null; p = p.subcommand()) {
            if (!p.unmatched().isEmpty()) {
                throw new CommandLine.UnmatchedArgumentException(p.commandSpec().commandLine(), p.unmatched());
            }
        }
        return new CommandLine.RunLast().execute(parsed);
    }

    /**
     * The word given where a command was expected ({@code parpe rn}, {@code parpe help rn}), or
     * {@code null}: the top level takes no values but commands.
     */
    private static String unknownCommand(CommandLine.ParameterException ex, CommandLine top) {
        if (ex instanceof CommandLine.UnmatchedArgumentException u && ex.getCommandLine() == top
                && !u.getUnmatched().isEmpty() && !u.getUnmatched().get(0).startsWith("-")) {
            return u.getUnmatched().get(0);
        }
        if (ex.getCommandLine() == top && ex.getArgSpec() == null && ex.getValue() != null
                && !ex.getValue().startsWith("-") && !top.getSubcommands().containsKey(ex.getValue())) {
            return ex.getValue(); // from picocli's help command: parpe help rn
        }
        return null;
    }

    /**
     * How a command that threw ends, for every command in one place: a {@link UsageException} (a
     * bad command-line value) is one line and exit code 2; anything else is a failure of PARPE
     * itself ({@link #internalError}).
     */
    public static int failed(Exception ex, CommandLine line, CommandLine.ParseResult parsed) {
        if (ex instanceof UsageException) {
            line.getErr().println("parpe: " + ex.getMessage());
            return 2;
        }
        return internalError(ex, line.getErr());
    }

    /** Reports a failure of PARPE itself: one line for the user, the details in a file. */
    static int internalError(Throwable ex, PrintStream err) {
        PrintWriter w = new PrintWriter(err, true, terminal);
        int code = internalError(ex, w);
        w.flush();
        return code;
    }

    private static int internalError(Throwable ex, PrintWriter err) {
        String where = CrashReport.write(Path.of(System.getProperty("java.io.tmpdir")), "running a command", ex);
        err.println("parpe: " + CliMsg.INTERNAL_ERROR.text(ex, where));
        return ExitCode.INTERNAL_ERROR;
    }
}
