package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * Bad input on the command line (issue 8 §4): every case ends with one clear message and exit
 * code 1 or 2 (4 for a failure of PARPE itself), never a stack trace, a hang or a crash.
 */
class BadInputTest {
    @TempDir
    Path dir;

    record Result(int code, String out, String err) {
    }

    static Result parpe(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> Main.execute(args,
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8)));
        Result r = new Result(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
        assertFalse(r.err().contains("Exception") || r.err().contains("\tat "), "stack trace on stderr:\n" + r.err());
        return r;
    }

    Path write(String name, String text) throws Exception {
        Path p = dir.resolve(name);
        Files.writeString(p, text);
        return p;
    }

    Path good() throws Exception {
        return write("good.xml", CliContractTest.GOOD);
    }

    @Test
    void nonAsciiDigitsAreLocatedScriptErrorsOrUsageErrors() throws Exception {
        Path p = write("arabic.xml", CliContractTest.GOOD.replace("phase=\"0.5\"", "phase=\"\u0663\""));
        Result r = parpe("check", p.toString());
        assertEquals(1, r.code(), r.err());
        assertTrue(r.err().contains("arabic.xml:6:35: error: '\u0663' (U+0663) is not an ASCII digit"), r.err());
        Result param = parpe("run", good().toString(), "--param", "amp=\u0663");
        assertEquals(2, param.code(), param.err());
        assertTrue(param.err().contains("parameter 'amp' must be a number, got '\u0663'"), param.err());
        Path stim = write("s.txt", "\u0661 $dir=down\n");
        Result s = parpe("run", good().toString(), "--stimulus", stim.toString());
        assertEquals(2, s.code(), s.err());
        assertTrue(s.err().contains("s.txt:1:1: error: time must be a number of seconds >= 0, got '\u0661'"), s.err());
    }

    @Test
    void devicesFifosAndHugeInputsAreRefusedWithoutHanging() throws Exception {
        Path fifo = dir.resolve("fifo.xml");
        new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor();
        Path big = dir.resolve("big.xml");
        Files.write(big, new byte[(int) org.parpe.core.xml.InputFiles.MAX_BYTES + 1]);
        for (String bad : List.of(fifo.toString(), big.toString(), "/dev/zero")) {
            String why = bad.equals(big.toString()) ? "larger than the limit of 16 MiB for an input file"
                    : "not a regular file";
            for (String[] args : List.of(new String[] {"check", bad}, new String[] {"run", bad},
                    new String[] {"race", bad}, new String[] {"run", good().toString(), "--stimulus", bad})) {
                Result r = parpe(args);
                assertEquals(2, r.code(), String.join(" ", args) + "\n" + r.err());
                assertTrue(r.err().contains("cannot read '" + bad + "': ") && r.err().contains(why), r.err());
            }
        }
    }

    @Test
    void tickAndDurationAreBounded() throws Exception {
        String script = good().toString();
        Result tiny = parpe("run", script, "--tick", "1e-320", "--duration", "1");
        assertEquals(2, tiny.code(), tiny.err());
        assertTrue(tiny.err().contains("--tick must be within [0.000001, 10] seconds, got 1.0E-320"), tiny.err());
        assertEquals(2, parpe("run", script, "--tick", "11").code());
        Result many = parpe("run", script, "--tick", "0.00001", "--duration", "1e5");
        assertEquals(2, many.code(), many.err());
        assertTrue(many.err().contains("is 10000000000 ticks; a run may take at most 1000000000 ticks"), many.err());
        Result race = parpe("race", script, "--tick", "1e-320");
        assertEquals(2, race.code(), race.err());
        assertTrue(race.err().contains("--tick must be within"), race.err());
        assertEquals(2, parpe("race", script, "--duration", "1e12").code());
    }

    @Test
    void everyCommandHasHelpAndUnknownCommandsGetASuggestion() {
        for (String name : new CommandLine(new Main()).getSubcommands().keySet()) {
            Result r = parpe(name, "--help");
            assertEquals(0, r.code(), name + ": " + r.err());
            assertTrue(r.out().contains("Usage: parpe " + name), name + ": " + r.out());
        }
        Result r = parpe("rn", "x.xml");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("unknown command 'rn' (did you mean 'run'?)"), r.err());
    }

    /** Issue 31 item 3.8: {@code parpe NOSUCH --help} printed the general help and exited 0. */
    @Test
    void helpForAnUnknownCommandSaysItIsUnknown() {
        for (String[] args : new String[][] {{"NOSUCH", "--help"}, {"--help", "NOSUCH"}, {"rn", "-h"}, {"help", "NOSUCH"}}) {
            Result r = parpe(args);
            assertEquals(2, r.code(), String.join(" ", args) + ": " + r.out() + r.err());
            assertEquals("", r.out(), "no help printed for " + String.join(" ", args));
            String word = args[0].startsWith("-") || args[0].equals("help") ? args[1] : args[0];
            assertTrue(r.err().startsWith("parpe: unknown command '" + word + "'"), r.err());
        }
        assertTrue(parpe("rn", "--help").err().contains("(did you mean 'run'?)"));
        assertTrue(parpe("NOSUCH", "--help").err().contains("commands are check, run,"));
        Result option = parpe("run", "--help", "--no-such-option");
        assertEquals(2, option.code(), option.out() + option.err());
        assertTrue(option.err().contains("--no-such-option"), option.err());
    }

    @Test
    void aRunWithoutDurationSaysHowItEnds() throws Exception {
        Result r = parpe("run", write("ends.xml", CliContractTest.GOOD.replace("sqrt(1 - $time)", "1")).toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("no --duration: the run lasts until <main> ends or Ctrl-C"), r.err());
        assertFalse(parpe("run", good().toString(), "--duration", "1").err().contains("no --duration"));
    }

    @Test
    void anInternalErrorHasItsOwnExitCode() throws Exception {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.internalError(new IllegalStateException("boom"), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(4, code);
        String message = err.toString(StandardCharsets.UTF_8);
        assertTrue(message.startsWith("parpe: internal error: "), message);
        String crash = message.substring(message.indexOf("please attach ") + 14, message.indexOf(" to a bug report"));
        assertTrue(Files.deleteIfExists(Path.of(crash)), message);
        assertTrue(parpe("--help").out().contains("4 internal error"));
    }
}
