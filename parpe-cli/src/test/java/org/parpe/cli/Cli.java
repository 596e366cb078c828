package org.parpe.cli;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;

/** Runs the command line in-process and keeps its exit code and output, for the tests of every command. */
public final class Cli {
    public final int code;
    public final String out;
    public final String err;

    private Cli(int code, String out, String err) {
        this.code = code;
        this.out = out;
        this.err = err;
    }

    /** Runs {@code parpe ARGS}. */
    public static Cli run(List<String> args) {
        return run(args.toArray(new String[0]));
    }

    /**
     * Runs {@code parpe ARGS} with nothing on its standard input: the forked test JVM's own
     * standard input carries Surefire's orders, and a command that read it (the emulator's
     * console) would keep the fork from ending for 30 s.
     */
    public static Cli run(String... args) {
        return withInput("", args);
    }

    /** Runs {@code parpe ARGS} with {@code input} as its standard input. */
    public static Cli withInput(String input, String... args) {
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        int code = Main.execute(args, new ByteArrayInputStream(input.getBytes(StandardCharsets.UTF_8)),
                new PrintStream(o, true, StandardCharsets.UTF_8), new PrintStream(e, true, StandardCharsets.UTF_8),
                System::getenv);
        return new Cli(code, o.toString(StandardCharsets.UTF_8), e.toString(StandardCharsets.UTF_8));
    }

    @Override
    public String toString() {
        return "exit " + code + "\nstdout:\n" + out + "\nstderr:\n" + err;
    }
}
