package org.parpe.cli.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.parpe.cli.Cli;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;

/** {@code parpe sweep}, {@code optimize} and {@code merge} end to end, and the Slurm array script. */
class SweepCommandTest {
    /** The sweep tests' wave snake with bounded parameters, shared with parpe-sim's sweep tests. */
    static final String SNAKE = read(Path.of("../parpe-sim/src/test/resources/sweep-snake.xml"));

    private static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @TempDir
    Path dir;
    Path script;

    @BeforeEach
    void writeScript() throws Exception {
        script = snakeIn(dir);
    }

    /** {@link #SNAKE} written to {@code snake.xml} in {@code dir}. */
    static Path snakeIn(Path dir) throws java.io.IOException {
        return Files.writeString(dir.resolve("snake.xml"), SNAKE);
    }

    private String[] sweepArgs(String out, String... more) {
        List<String> a = new ArrayList<>(List.of("sweep", script.toString(), "--sim", "snake:n=6", "--duration", "1",
                "--vary", "bend=20..40:3", "--vary", "period=1,2", "--param", "phase=0.2", "--out", out));
        a.addAll(List.of(more));
        return a.toArray(new String[0]);
    }

    @Test
    void theSameSeedGivesTheSameCsvWhateverTheJobs() throws Exception {
        Path a = dir.resolve("a.csv");
        Path b = dir.resolve("b.csv");
        Cli ra = Cli.run("sweep", script.toString(), "--sim", "snake:n=6", "--duration", "1", "--random", "5",
                "--seed", "3", "--jobs", "1", "--out", a.toString());
        Cli rb = Cli.run("sweep", script.toString(), "--sim", "snake:n=6", "--duration", "1", "--random", "5",
                "--seed", "3", "--jobs", "2", "--out", b.toString());
        assertEquals(0, ra.code, ra.err);
        assertEquals(0, rb.code, rb.err);
        List<String> lines = Files.readAllLines(a);
        assertEquals(lines, Files.readAllLines(b));
        assertEquals(6, lines.size());
        assertEquals("run,runs,combination,repeat,seed,bend,period,phase,duration_s,distance_m,forward_m,"
                + "forward_speed_mps,speed_mps,max_tilt_deg,joint_travel_deg,fell,error", lines.get(0));
        assertTrue(lines.get(1).startsWith("0,5,0,0,3,"), lines.get(1));
        Cli other = Cli.run("sweep", script.toString(), "--sim", "snake:n=6", "--duration", "1", "--random", "5",
                "--seed", "4", "--out", dir.resolve("c.csv").toString());
        assertEquals(0, other.code, other.err);
        assertFalse(Files.readAllLines(dir.resolve("c.csv")).get(1).equals(lines.get(1)));
        BufferedImage plot = ImageIO.read(dir.resolve("a.png").toFile());
        assertTrue(plot.getWidth() >= 800 && plot.getHeight() >= 3 * 250, plot.getWidth() + "x" + plot.getHeight());
    }

    @Test
    void gridRowsAreInCombinationOrderAndTheBestIsReported() throws Exception {
        Cli r = Cli.run(sweepArgs("-"));
        assertEquals(0, r.code, r.err);
        List<String> lines = r.out.lines().toList();
        assertEquals(7, lines.size());
        for (int i = 1; i <= 6; i++) {
            assertTrue(lines.get(i).startsWith((i - 1) + ",6,"), lines.get(i));
        }
        assertTrue(lines.get(3).startsWith("2,6,2,0,0,30,1,"), lines.get(3));
        assertTrue(r.err.contains("parpe: 6 of 6 runs; 0 with errors"), r.err);
        assertTrue(r.err.contains("parpe: best forward-speed "), r.err);
    }

    /**
     * Issue 31 item 3.2: a best value at an end of its {@code --vary} range is flagged (the best
     * may lie beyond it); one inside, or of a single value, is not.
     */
    @Test
    void aBestValueAtAnEndOfItsRangeIsFlagged() {
        Cli r = Cli.run(sweepArgs("-"));
        assertEquals(0, r.code, r.err);
        java.util.regex.Matcher best = java.util.regex.Pattern.compile("parpe: best forward-speed \\S+ with bend=(\\S+)"
                + " period=(\\S+) \\(run").matcher(r.err);
        assertTrue(best.find(), r.err);
        String bend = best.group(1);
        String period = best.group(2);
        String bendFlag = "parpe: best bend=" + bend + " is at its " + (bend.equals("40") ? "upper" : "lower") + " bound "
                + bend + ": widen the range";
        assertEquals(!bend.equals("30"), r.err.contains(bendFlag), r.err);
        assertEquals(bend.equals("30"), !r.err.contains("parpe: best bend="), r.err);
        assertTrue(r.err.contains("parpe: best period=" + period + " is at its " + (period.equals("2") ? "upper" : "lower")
                + " bound " + period + ": widen the range"), "the grid's period is 1 or 2: " + r.err);
        Cli single = Cli.run("sweep", script.toString(), "--sim", "snake:n=6", "--duration", "1", "--vary", "bend=30",
                "--out", "-");
        assertEquals(0, single.code, single.err);
        assertFalse(single.err.contains("bound"), "one value has no range to widen: " + single.err);
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "bnd=1..2|parpe: --vary bnd=1..2: unknown parameter 'bnd' (did you mean 'bend'?); the script's parameters are bend, period, phase",
        "bend=40..10|parpe: --vary bend=40..10: empty range: the start 40 is greater than the end 10",
        "bend=10..40:0|parpe: --vary bend=10..40:0: K (the number of values) must be >= 1, got 0",
        "bend=10..90:3|parpe: --vary bend=10..90:3: parameter 'bend' must be <= 60, got 90 (its bounds are 0..60)",
        "period=0.5..2|parpe: --vary period=0.5..2 has fractional ends, so a grid needs a number of values: write period=0.5..2:K, or draw with --random COUNT",
        "bend|parpe: --vary 'bend': expected NAME=A..B, NAME=A..B:K or NAME=V1,V2,...",
    })
    void badVarySpecsGetOneLineAndExitCode2(String vary, String message) {
        Cli r = Cli.run("sweep", script.toString(), "--sim", "snake:n=6", "--vary", vary, "--out", "-");
        assertEquals(2, r.code, r.err);
        assertEquals(message, r.err.strip());
        assertEquals("", r.out);
    }

    @Test
    void badShardsAndObjectivesAreUsageErrors() {
        Cli shard = Cli.run(sweepArgs("-", "--shard", "4/3"));
        assertEquals(2, shard.code);
        assertEquals("parpe: --shard 4/3: K must be within [1, N] and N >= 1", shard.err.strip());
        Cli goal = Cli.run(sweepArgs("-", "--objective", "fast"));
        assertEquals(2, goal.code);
        assertEquals("parpe: --objective must be one of forward-speed, speed, forward, distance, score, got 'fast'",
                goal.err.strip());
    }

    @Test
    void optimizeWritesANewScriptWithTheBestValuesAsDefaults() throws Exception {
        Cli r = Cli.run("optimize", script.toString(), "--sim", "snake:n=6", "--duration", "2", "--budget", "12",
                "--starts", "2", "--seed", "5");
        assertEquals(0, r.code, r.err);
        Path written = dir.resolve("snake-optimised.xml");
        assertTrue(Files.exists(dir.resolve("snake-optimised-convergence.png")), r.err);
        assertEquals(SNAKE, Files.readString(script));
        LoadResult loaded = ScriptLoader.load(written, Map.of());
        assertTrue(loaded.ok(), loaded.diagnostics().toString());
        for (var p : loaded.program().parameters()) {
            assertTrue(r.out.contains("  " + p.name() + " = " + org.parpe.core.lang.Numbers.format(p.value())),
                    p + "\n" + r.out);
        }
        assertTrue(r.out.startsWith("best forward-speed: "), r.out);
        assertTrue(r.out.contains("the script's own values: "), r.out);
    }

    @Test
    void optimizeNeverOverwritesTheScript() throws Exception {
        Cli r = Cli.run("optimize", script.toString(), "--sim", "snake:n=6", "--budget", "4", "--starts", "1",
                "--out", script.toString());
        assertEquals(2, r.code);
        assertTrue(r.err.startsWith("parpe: cannot write --out file '" + script + "': it is the input file"), r.err);
        assertEquals(SNAKE, Files.readString(script));
    }
}
