package org.parpe.cli.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;

/** Goals beside the figures of {@code parpe bench}, saved runs and two runs side by side (issue 36). */
class BenchResultsTest {
    private static final List<Goal> GOALS = List.of(Goal.atLeast("scheduler.module_updates_per_s", 30e6),
            Goal.atMost("sim.*.bytes_per_tick", 1024), Goal.atLeast("sweep.*.speedup", 1.8));

    @Test
    void aFigureWithAGoalShowsTheGoalAndWhetherItHolds() {
        BenchResults r = new BenchResults(GOALS);
        assertEquals("scheduler.module_updates_per_s=31000000  # goal >= 30000000: holds",
                r.take("scheduler.module_updates_per_s=31000000"));
        assertEquals("sim.centipede55.bytes_per_tick=2048  # goal <= 1024: MISSED", r.take("sim.centipede55.bytes_per_tick=2048"));
        assertEquals("sim.snake8.bytes_per_tick=0  # goal <= 1024: holds", r.take("sim.snake8.bytes_per_tick=0"));
        assertEquals("scheduler.modules=1000", r.take("scheduler.modules=1000"));
        assertEquals("# core", r.take("# core"));
        assertEquals("serial.pty_fps=skipped (socat is not installed)", r.take("serial.pty_fps=skipped (socat is not installed)"));
        // a line that already carries its verdict (the output of a forked benchmark, a saved output) is read as its figure
        assertEquals("sim.snake8.bytes_per_tick=10  # goal <= 1024: holds", r.take("sim.snake8.bytes_per_tick=10  # goal <= 1024: holds"));
        assertEquals("# goals: 2 held, 1 missed (sim.centipede55.bytes_per_tick); not measured: sweep.*.speedup", r.summary());
    }

    @Test
    void aPatternStandsForAnyPartOfANameOnly() {
        Goal g = Goal.atLeast("sweep.*.speedup", 1.8);
        assertTrue(g.appliesTo("sweep.snake8.speedup"));
        assertTrue(!g.appliesTo("sweep.snake8.speedup_of_medians"));
        assertTrue(!g.appliesTo("sweepXsnake8Xspeedup"), "the dots are dots, not any character");
    }

    @Test
    void linesPrintedByABenchmarkReachTheOutputWithTheirGoals() {
        BenchResults r = new BenchResults(GOALS);
        StringWriter shown = new StringWriter();
        PrintStream out = r.printer(new PrintWriter(shown, true));
        out.printf("scheduler.module_updates_per_s=%d%n", 12_000_000);
        out.println("scheduler.modules=1000");
        assertEquals("scheduler.module_updates_per_s=12000000  # goal >= 30000000: MISSED\nscheduler.modules=1000\n",
                shown.toString().replace(System.lineSeparator(), "\n"));
        assertEquals("scheduler.module_updates_per_s=12000000\nscheduler.modules=1000\n", r.text());
    }

    @Test
    void twoSavedRunsSideBySide(@TempDir Path dir) throws Exception {
        Path before = dir.resolve("before.txt");
        Path after = dir.resolve("after.txt");
        Files.writeString(before, "# core\nscheduler.modules=1000\nscheduler.module_updates_per_s=20000000"
                + "  # goal >= 30000000: MISSED\nscheduler.bytes_allocated_per_tick=0.00\n", StandardCharsets.UTF_8);
        Files.writeString(after, "scheduler.modules=1000\nscheduler.module_updates_per_s=31000000\n"
                + "scheduler.bytes_allocated_per_tick=0.00\nexport.c_over_java=3.10\n", StandardCharsets.UTF_8);
        List<String> lines = sideBySide(before, after);
        assertEquals(5, lines.size(), lines::toString);
        assertTrue(lines.get(0).matches("figure +" + java.util.regex.Pattern.quote(before.toString()) + " +"
                + java.util.regex.Pattern.quote(after.toString()) + " +change +goal"), lines.get(0));
        assertTrue(lines.get(1).matches("scheduler\\.modules +1000 +1000 +\\+0\\.0%"), lines.get(1));
        assertTrue(lines.get(2).matches("scheduler\\.module_updates_per_s +20000000 +31000000 +\\+55\\.0%"
                + " +>= 30000000: MISSED -> holds"), lines.get(2));
        assertTrue(lines.get(3).matches("scheduler\\.bytes_allocated_per_tick +0\\.00 +0\\.00 +<= 0: holds -> holds"),
                lines.get(3));
        assertTrue(lines.get(4).matches("export\\.c_over_java +- +3\\.10 +>= 3: - -> holds"), lines.get(4));
    }

    @Test
    void compareRefusesAThirdFileAndAnUnreadableOne(@TempDir Path dir) {
        Path missing = dir.resolve("missing.txt");
        Cli c = Cli.run("bench", "--compare", missing.toString());
        assertEquals(2, c.code, c::toString);
        assertTrue(c.err.contains("cannot read " + missing), c::toString);
        Cli three = Cli.run("bench", "--compare", "a", "--compare", "b", "--compare", "c");
        assertEquals(2, three.code, three::toString);
    }

    /** The head of /proc/cpuinfo on the 2-core KVM machine of 2026-11-29 (one processor of two shown). */
    private static final String EPYC = "processor\t: 0\nvendor_id\t: AuthenticAMD\ncpu family\t: 25\nmodel\t\t: 1\n"
            + "model name\t: AMD EPYC\nstepping\t: 1\ncpu MHz\t\t: 2445.428\ncache size\t: 512 KB\n";

    @Test
    void aRunNamesTheMachineItMeasured() {
        assertEquals(List.of("machine.cpu=AMD EPYC", "machine.cores=2", "machine.cpu_mhz=2445", "machine.java=OpenJDK 17.0.15",
                "machine.load_average=0.75"), Machine.lines(EPYC, 2, "OpenJDK 17.0.15", 0.75));
        // no /proc/cpuinfo (not Linux) and no load average (Windows): the architecture, nothing guessed
        assertEquals(List.of("machine.cpu=" + System.getProperty("os.arch"), "machine.cores=8", "machine.java=J"),
                Machine.lines("", 8, "J", -1));
        // a model name padded with runs of spaces, as some processors report it
        assertEquals("machine.cpu=Intel(R) Xeon(R) CPU E5-2690 v4 @ 2.60GHz",
                Machine.lines("model name\t: Intel(R) Xeon(R) CPU E5-2690 v4   @ 2.60GHz\n", 1, "J", -1).get(0));
        List<String> here = Machine.lines();
        assertTrue(here.get(0).startsWith("machine.cpu=") && here.get(0).length() > "machine.cpu=".length(), here::toString);
        assertEquals("machine.cores=" + Runtime.getRuntime().availableProcessors(), here.get(1));
    }

    @Test
    void runsFromTwoMachinesAreSaidNotToCompare(@TempDir Path dir) throws Exception {
        Path zen = dir.resolve("zen.txt");
        Path epyc = dir.resolve("epyc.txt");
        Path epycAgain = dir.resolve("epyc2.txt");
        Files.writeString(zen, "machine.cpu=AMD Ryzen 9 9950X\nmachine.cores=2\nsim.snake200.realtime_factor=18.5\n",
                StandardCharsets.UTF_8);
        Files.writeString(epyc, "machine.cpu=AMD EPYC\nmachine.cores=2\nmachine.load_average=0.75\n"
                + "sim.snake200.realtime_factor=8.5\n", StandardCharsets.UTF_8);
        Files.writeString(epycAgain, "machine.cpu=AMD EPYC\nmachine.cores=2\nmachine.load_average=1.75\n"
                + "sim.snake200.realtime_factor=8.4\n", StandardCharsets.UTF_8);
        List<String> lines = sideBySide(zen, epyc);
        assertTrue(lines.get(1).matches("machine\\.cpu +AMD Ryzen 9 9950X +AMD EPYC"), lines.get(1));
        assertTrue(lines.get(2).matches("machine\\.cores +2 +2"), "no change in per cent for the machine: " + lines.get(2));
        assertEquals("# the two runs come from different machines (AMD Ryzen 9 9950X × 2; AMD EPYC × 2): their times do not"
                + " compare, only their counts and bytes", lines.get(lines.size() - 1));
        List<String> same = sideBySide(epyc, epycAgain);
        assertTrue(same.stream().noneMatch(l -> l.startsWith("#")), same::toString);
        assertTrue(same.stream().anyMatch(l -> l.contains("-1.2%")), same::toString);
    }

    /** The lines of {@code parpe bench --compare A --compare B}, which must succeed. */
    private static List<String> sideBySide(Path a, Path b) {
        Cli c = Cli.run("bench", "--compare", a.toString(), "--compare", b.toString());
        assertEquals(0, c.code, c::toString);
        return c.out.lines().map(String::stripTrailing).toList();
    }
}
