package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 18's defects of the command line's outputs, each of which lost a file or exited 0
 * before the output policy (items 2, 5, 6, 8, 9, 10, 11).
 */
class OutputPolicyTest {
    /** A two-module wave with a parameter to vary. */
    static final String WAVE = """
            <program>
              <robot><structure><body elements="0..1"/></structure></robot>
              <parameters>
                <bend value="10" min="0" max="60"/>
              </parameters>
              <main><go/></main>
              <behaviors><go><wave group="body" period="2"/></go></behaviors>
              <automata><wave states="up, down"/></automata>
              <states><up angles="bend"/><down angles="-bend"/></states>
            </program>
            """;

    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text);
    }

    private static void refused(Cli r, String what) {
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains(what), r.err);
    }

    @Test
    void theHardwareProfileIsAnInputOfRunAndRecord() throws Exception {
        Path x = write("x.xml", CliContractTest.GOOD);
        String profile = "<hardware protocol=\"dxl2\" port=\"/dev/null\" baud=\"1000000\"/>\n";
        Path prof = write("prof.xml", profile);
        for (String option : List.of("--trace", "--metrics")) {
            Cli r = Cli.run("run", x.toString(), "--duration", "0.1", "--hardware", prof.toString(), option, prof.toString());
            refused(r, "it is the input file '" + prof + "'");
        }
        Cli rec = Cli.run("record", "--hardware", prof.toString(), "--group", "g", "--modules", "0..1",
                "--out", prof.toString());
        refused(rec, "it is the input file '" + prof + "'");
        assertEquals(profile, Files.readString(prof));
    }

    @Test
    void twoOutputsNamingOneFileAreRefused() throws Exception {
        Path x = write("x.xml", CliContractTest.GOOD);
        Path snake = write("snake.xml", WAVE);
        Path r = dir.resolve("r.csv");
        refused(Cli.run("sweep", snake.toString(), "--sim", "snake:n=2", "--duration", "0.1", "--vary", "bend=20..40:2",
                "--out", r.toString(), "--plot", r.toString()), "it is also the --out file");
        refused(Cli.run("optimize", snake.toString(), "--sim", "snake:n=2", "--duration", "0.1", "--budget", "8",
                "--out", r.toString(), "--plot", dir.resolve(".").resolve("r.csv").toString()), "it is also the --out file");
        refused(Cli.run("run", x.toString(), "--duration", "0.1", "--trace", r.toString(), "--sim", "--plot", r.toString()),
                "it is also the --trace file");
        refused(Cli.run("run", x.toString(), "--duration", "0.1", "--trace", r.toString(), "--sim", "--metrics",
                r.toString()), "it is also the --trace file");
        assertTrue(!Files.exists(r));
    }

    @Test
    void optimizeKeepsAnExistingOptimisedScriptWithoutAnExplicitChoice() throws Exception {
        Path snake = write("snake.xml", WAVE);
        Path mine = write("snake-optimised.xml", "<!-- hand-edited -->\n");
        refused(Cli.run("optimize", snake.toString(), "--sim", "snake:n=2", "--duration", "0.1", "--budget", "8"),
                "cannot write --out file '" + mine + "': it exists; name the file with --out, or add --force");
        assertEquals("<!-- hand-edited -->\n", Files.readString(mine));
    }

    @Test
    void mergeNeutralisesForeignCellsASpreadsheetWouldEvaluate() throws Exception {
        String header = "run,runs,combination,repeat,seed,amp,duration_s,distance_m,forward_m,forward_speed_mps,speed_mps,"
                + "max_tilt_deg,joint_travel_deg,fell,error";
        Path a = write("a.csv", header + "\n0,2,0,0,1,-1.5,1.000000,0.1,0.1,0.1,0.1,1.0,2.0,0,\n");
        Path b = write("b.csv", header + "\n1,2,1,0,1,=1+1,1.000000,0.1,0.1,0.1,0.1,1.0,2.0,0,\"@SUM(A1)\"\n");
        Path out = dir.resolve("m.csv");
        Cli r = Cli.run("merge", a.toString(), b.toString(), "--out", out.toString());
        assertEquals(0, r.code, r.toString());
        List<String> lines = Files.readAllLines(out);
        assertEquals("0,2,0,0,1,-1.5,1.000000,0.1,0.1,0.1,0.1,1.0,2.0,0,", lines.get(1));
        assertEquals("1,2,1,0,1,'=1+1,1.000000,0.1,0.1,0.1,0.1,1.0,2.0,0,\"'@SUM(A1)\"", lines.get(2));
    }

    @Test
    void sweepToAClosedStandardOutputFails() throws Exception {
        Path snake = write("snake.xml", WAVE);
        PrintStream closed = new PrintStream(new OutputStream() {
            @Override
            public void write(int b) throws IOException {
                throw new IOException("Broken pipe");
            }
        }, true, StandardCharsets.UTF_8);
        java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
        int code = Main.execute(new String[] {"sweep", snake.toString(), "--sim", "snake:n=2", "--duration", "0.1",
            "--vary", "bend=20..40:2", "--out", "-"}, closed, new PrintStream(err, true, StandardCharsets.UTF_8));
        String said = err.toString(StandardCharsets.UTF_8);
        assertEquals(2, code, said);
        assertTrue(said.contains("cannot write to standard output"), said);
    }

    @Test
    void hugeSweepsAreRefusedAtOnce() throws Exception {
        Path snake = write("snake.xml", WAVE);
        Cli grid = Cli.run("sweep", snake.toString(), "--sim", "snake:n=2", "--duration", "0.1",
                "--vary", "bend=0..40:999999999", "--out", dir.resolve("g.csv").toString());
        assertTrue(grid.code != 0 && grid.code != 4, grid.toString());
        assertTrue(grid.err.contains("999999999 runs"), grid.err);
        Path wide = write("wide.xml", WAVE.replace("<bend value=\"10\" min=\"0\" max=\"60\"/>",
                "<bend value=\"10\" min=\"0\" max=\"1000000000000\"/>"));
        Cli random = Cli.run("sweep", wide.toString(), "--sim", "snake:n=2", "--duration", "0.1", "--random", "2",
                "--out", dir.resolve("w.csv").toString());
        assertEquals(0, random.code, random.toString());
        assertEquals(3, Files.readAllLines(dir.resolve("w.csv")).size());
    }

    @Test
    void emulateLogGoesThroughTheRules() throws Exception {
        Path x = write("x.xml", CliContractTest.GOOD);
        refused(Cli.run("emulate", "--port", dir.resolve("p").toString(), "--modules", "0..1", "--log", "/dev/null"),
                "cannot write --log file '/dev/null': it is not a regular file");
        refused(Cli.run("emulate", "--port", dir.resolve("p").toString(), "--modules", "0..1", "--log", dir.toString()),
                "it is a directory");
        assertEquals(CliContractTest.GOOD, Files.readString(x));
    }
}
