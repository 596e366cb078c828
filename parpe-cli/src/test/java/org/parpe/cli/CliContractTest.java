package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The CLI contract of PARSL.md §11: exit codes, located messages, trace rules, never a stack trace. */
class CliContractTest {
    @TempDir
    Path dir;

    record Result(int code, String out, String err) {
    }

    Result parpe(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.execute(args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        Result r = new Result(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
        assertFalse(r.err().contains("Exception") || r.err().contains("\tat "), "stack trace on stderr:\n" + r.err());
        return r;
    }

    Path write(String name, String text) throws Exception {
        Path p = dir.resolve(name);
        Files.writeString(p, text);
        return p;
    }

    static final String GOOD = "<program>\n<robot><structure><g elements=\"0, 1\"/></structure></robot>\n"
            + "<parameters><amp value=\"20\" min=\"0\" max=\"45\"/></parameters>\n"
            + "<controls><dir type=\"radio\" values=\"up, down\"/></controls>\n"
            + "<main><b time=\"2\"/></main>\n<behaviors><b><w group=\"g\" phase=\"0.5\"/></b></behaviors>\n"
            + "<automata><w states=\"s, t\"/></automata>\n"
            + "<states><s angles=\"amp * sqrt(1 - $time)\"/><t angles=\"-amp\"/></states>\n</program>\n";

    @Test
    void checkReportsOkAndErrors() throws Exception {
        Path good = write("good.xml", GOOD);
        Result ok = parpe("check", good.toString());
        assertEquals(0, ok.code(), ok.err());
        assertTrue(ok.out().contains("good.xml: ok"));
        Path bad = write("bad.xml", GOOD.replace("states=\"s, t\"", "states=\"s, tt\"").replace("phase=\"0.5\"", "phase=\"0.5 *\""));
        Result r = parpe("check", bad.toString());
        assertEquals(1, r.code());
        List<String> lines = r.err().lines().filter(l -> l.contains(": error: ")).toList();
        assertEquals(2, lines.size(), r.err());
        assertTrue(lines.stream().allMatch(l -> l.matches(".*bad\\.xml:\\d+:\\d+: error: .*")), r.err());
        assertEquals(2, parpe("check", dir.resolve("missing.xml").toString()).code());
    }

    @Test
    void runWritesTheTraceUpToTheDurationAndStopsOnARunTimeError() throws Exception {
        Path good = write("good.xml", GOOD);
        Path trace = dir.resolve("t.csv");
        Result r = parpe("run", good.toString(), "--duration", "0.5", "--trace", trace.toString());
        assertEquals(0, r.code(), r.err());
        List<String> rows = Files.readAllLines(trace);
        assertEquals("time,m0,m1", rows.get(0));
        assertEquals(52, rows.size());
        assertTrue(rows.get(51).startsWith("0.500000,"), rows.get(51));
        Result failing = parpe("run", good.toString(), "--tick", "0.005", "--duration", "2", "--trace", trace.toString());
        assertEquals(3, failing.code(), failing.err());
        assertTrue(failing.err().contains("good.xml:8:20: error: sqrt() of -0.005 is not a finite number in 'amp * sqrt(1 - $time)'"),
                failing.err());
        assertTrue(failing.err().contains("(at t=1.005000 s)"), failing.err());
        assertEquals(1 + 201, Files.readAllLines(trace).size(), "rows up to t=1.0 are kept; the failing tick is not written");
    }

    @Test
    void aNegativeStateDurationExitsThreeNamingAutomatonStateAndValue() throws Exception {
        // PARSL 1.0.1 §13 rule 21: the second duration becomes negative after t = 0.5
        Path p = write("neg.xml", GOOD.replace("<w states=\"s, t\"/>", "<w states=\"s, t\" times=\"1, 0.5 - $time\"/>"));
        Path trace = dir.resolve("neg.csv");
        Result r = parpe("run", p.toString(), "--tick", "0.1", "--trace", trace.toString());
        assertEquals(3, r.code(), r.err());
        assertTrue(r.err().contains("neg.xml:7:38: error: state 't' of automaton 'w' has a negative duration: -0.1 s"), r.err());
        assertTrue(r.err().contains("(at t=0.600000 s)"), r.err());
        assertEquals(1 + 6, Files.readAllLines(trace).size(), "rows t=0..0.5 are kept");
    }

    @Test
    void badParametersAndStimuliAreUsageErrors() throws Exception {
        Path good = write("good.xml", GOOD);
        Result unknown = parpe("run", good.toString(), "--param", "ampl=3");
        assertEquals(2, unknown.code());
        assertTrue(unknown.err().contains("--param ampl: error: unknown parameter 'ampl' (did you mean 'amp'?)"), unknown.err());
        Result range = parpe("run", good.toString(), "--param", "amp=90");
        assertEquals(2, range.code());
        // Located at the parameter's definition, whose bound the value breaks.
        assertTrue(range.err().matches("(?s).*good\\.xml:\\d+:\\d+: error: parameter 'amp' must be <= 45, got 90.*"), range.err());
        assertEquals(2, parpe("run", good.toString(), "--param", "amp=lots").code());
        Path stim = write("s.txt", "# comment\n0.5 $dir=down\n1.0 $dir=sideways\n");
        Result s = parpe("run", good.toString(), "--stimulus", stim.toString());
        assertEquals(2, s.code());
        assertTrue(s.err().contains("s.txt:3:1: error: radio 'dir' has no word 'sideways'"), s.err());
        assertEquals(2, parpe("run", good.toString(), "--no-such-option").code());
        assertEquals(2, parpe("run", dir.resolve("nope.xml").toString()).code());
        assertEquals(2, parpe("run", good.toString(), "--tick", "0").code());
    }

    @Test
    void aProgramWithoutMainWarnsAndWritesNoTrace() throws Exception {
        Path p = write("nomain.xml", "<program><robot><structure><g elements=\"0\"/></structure></robot></program>");
        Path trace = dir.resolve("t.csv");
        Result r = parpe("run", p.toString(), "--trace", trace.toString());
        assertEquals(0, r.code());
        assertTrue(r.err().contains("warning: the program has no <main>"), r.err());
        assertFalse(Files.exists(trace));
    }

    @Test
    void scriptErrorsExitOne() throws Exception {
        Path p = write("broken.xml", "<program><robot><structure><g elements=\"0\"/></structure></robot><main><nothing/></main></program>");
        Result r = parpe("run", p.toString());
        assertEquals(1, r.code());
        assertTrue(r.err().contains("broken.xml:1:"), r.err());
    }
}
