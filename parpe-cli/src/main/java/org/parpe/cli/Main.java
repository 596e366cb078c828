package org.parpe.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.parpe.cli.bench.BenchCommand;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code parpe} command line: checks and runs PARSL scripts headless. */
@Command(name = "parpe", mixinStandardHelpOptions = true, version = "PARPE 0.1.0",
        description = "PolyKinetic Phase Automata Robot Programming Environment: check and run PARSL scripts.",
        subcommands = {
            CheckCommand.class,
            RunCommand.class,
            BenchCommand.class,
            org.parpe.cli.sim.RaceCommand.class,
            org.parpe.cli.hw.EmulateCommand.class,
            org.parpe.cli.hw.RecordCommand.class,
            org.parpe.cli.hw.ScanCommand.class,
            org.parpe.cli.hw.CalibrateCommand.class,
            CommandLine.HelpCommand.class
        },
        footer = {"", "  gui [FILE] [--run-for S] [--screenshot F.png] [--exit]",
                  "          Open the IDE (./parpe with no arguments does the same).",
                  "", "Exit codes: 0 success, 1 script errors, 2 usage errors, 3 run-time error."})
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

    /** Runs the command line with the given streams; returns the exit code. */
    public static int execute(String[] args, PrintStream out, PrintStream err) {
        CommandLine cl = new CommandLine(new Main());
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        cl.setExecutionExceptionHandler((ex, line, parsed) -> internalError(ex, err));
        cl.setParameterExceptionHandler((ex, args2) -> {
            err.println("parpe: " + ex.getMessage());
            CommandLine.UnmatchedArgumentException.printSuggestions(ex, err);
            err.println("Try 'parpe " + (ex.getCommandLine() == cl ? "" : ex.getCommandLine().getCommandName() + " ")
                    + "--help' for usage.");
            return 2;
        });
        return cl.execute(args);
    }

    /** Reports a failure of PARPE itself: one line for the user, the details in a file. */
    static int internalError(Throwable ex, PrintStream err) {
        StringWriter trace = new StringWriter();
        ex.printStackTrace(new PrintWriter(trace));
        String where;
        try {
            Path f = Files.createTempFile("parpe-crash-", ".txt");
            Files.writeString(f, "PARPE 0.1.0 internal error\n" + trace);
            where = f.toString();
        } catch (IOException io) {
            where = "(could not write a crash file: " + io.getMessage() + ")";
        }
        err.println("parpe: internal error: " + ex + "; please attach " + where + " to a bug report");
        return 3;
    }
}
