package org.parpe.cli;

import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.file.Path;
import org.parpe.cli.bench.BenchCommand;
import org.parpe.cli.options.UsageException;
import org.parpe.cli.terminal.ExitCode;
import org.parpe.core.expr.Names;
import org.parpe.core.io.CrashReport;
import picocli.CommandLine;
import picocli.CommandLine.Command;

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
        System.exit(execute(args, System.out, System.err));
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
        // Without the IDE (the command-line jar alone), `parpe` with no arguments prints the usage.
        if (Ide.wanted(args) && (args.length > 0 || Ide.present())) {
            return Ide.open(args, err);
        }
        CommandLine cl = new CommandLine(new Main());
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        cl.setExecutionExceptionHandler(Main::failed);
        cl.setExecutionStrategy(Main::executeMatched);
        cl.setParameterExceptionHandler((ex, args2) -> {
            String command = unknownCommand(ex, cl);
            if (command != null) {
                err.println("parpe: unknown command '" + command + "'" + Names.suggest(command,
                        cl.getSubcommands().keySet()) + "; commands are " + String.join(", ", cl.getSubcommands().keySet())
                        + " and gui");
            } else {
                err.println("parpe: " + ex.getMessage());
                CommandLine.UnmatchedArgumentException.printSuggestions(ex, err);
            }
            err.println("Try 'parpe " + (ex.getCommandLine() == cl ? "" : ex.getCommandLine().getCommandName() + " ")
                    + "--help' for usage.");
            return 2;
        });
        try {
            return cl.execute(args);
        } catch (OutOfMemoryError e) {
            // inputs are capped at 16 MiB, which loads in well under 1 GiB; a smaller heap may not do
            err.println("parpe: out of memory with a Java heap of " + (Runtime.getRuntime().maxMemory() >> 20)
                    + " MiB; allow more with JAVA_TOOL_OPTIONS=-Xmx1g");
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
        PrintWriter w = new PrintWriter(err, true);
        int code = internalError(ex, w);
        w.flush();
        return code;
    }

    private static int internalError(Throwable ex, PrintWriter err) {
        String where = CrashReport.write(Path.of(System.getProperty("java.io.tmpdir")), "running a command", ex);
        err.println("parpe: internal error: " + ex + "; please attach " + where + " to a bug report");
        return ExitCode.INTERNAL_ERROR;
    }
}
