package org.parpe.cli.grade;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;

/**
 * Grading as a sweep-like array (issue 37: "on Slurm through the existing sharding and merge"):
 * the shards of {@code parpe grade --shard K/N}, merged by {@code --merge N}, give the report
 * and traces a one-machine grading writes, byte for byte; a missing shard is named with its
 * students and the merge writes no report.
 */
class GradeShardsTest {
    @TempDir
    Path dir;

    private Path students() throws Exception {
        Path s = Files.createDirectories(dir.resolve("students"));
        String[] bends = {"15", "30", "45", "30"};
        for (int i = 0; i < bends.length; i++) {
            Files.writeString(s.resolve("s" + i + ".xml"), GradeCommandTest.snake(bends[i], "<main><race/></main>"));
        }
        Files.writeString(s.resolve("broken\n\"name\".xml"), "<program>\n  <robot>\n</program>\n");
        Files.writeString(s.resolve("runtime.xml"), GradeCommandTest.snake("20", "<main><race/></main>")
                .replace("angles=\"bend\"", "angles=\"bend * sqrt(0.5 - $time)\""));
        return s;
    }

    private Path challenge() throws Exception {
        Path world = Path.of("../examples/worlds/race-track.xml").toAbsolutePath().normalize();
        return Files.writeString(dir.resolve("race.xml"), "<challenge world=\"" + world + "\" robot=\"snake:n=8\""
                + " duration=\"2\" tick=\"0.01\" max-modules=\"8\" tie-break=\"distance\"/>\n");
    }

    private static List<String> files(Path root) throws Exception {
        try (Stream<Path> s = Files.walk(root)) {
            return s.filter(Files::isRegularFile).map(p -> root.relativize(p).toString())
                    .filter(n -> !n.endsWith(".grade")).sorted().toList();
        }
    }

    @Test
    void mergedShardsGiveTheReportOfOneMachine() throws Exception {
        Path s = students();
        Path c = challenge();
        Path one = dir.resolve("one");
        Path split = dir.resolve("split");
        Cli local = Cli.run("grade", c.toString(), s.toString(), "--out", one.toString(), "--jobs", "2");
        assertEquals(0, local.code, local.toString());
        for (String k : List.of("3/3", "1/3", "2/3")) {
            Cli shard = Cli.run("grade", c.toString(), s.toString(), "--out", split.toString(), "--jobs", "1", "--shard", k);
            assertEquals(0, shard.code, shard.toString());
        }
        assertFalse(Files.exists(split.resolve("report.csv")), "a shard writes no report");
        Cli merged = Cli.run("grade", c.toString(), s.toString(), "--out", split.toString(), "--merge", "3");
        assertEquals(0, merged.code, merged.toString());
        assertEquals(local.out, merged.out.replace(split.toString(), one.toString()));
        assertEquals(files(one), files(split));
        for (String f : files(one)) {
            assertArrayEquals(Files.readAllBytes(one.resolve(f)), Files.readAllBytes(split.resolve(f)), f);
        }
        assertTrue(Files.readString(one.resolve("report.csv")).lines().count() >= 7, "the class is in the report");
    }

    @Test
    void aMissingShardIsNamedAndNoReportIsWritten() throws Exception {
        Path s = students();
        Path c = challenge();
        Path split = dir.resolve("split");
        Cli first = Cli.run("grade", c.toString(), s.toString(), "--out", split.toString(), "--shard", "1/2");
        assertEquals(0, first.code, first.toString());
        assertEquals("shard 1/2: students 1..3 of 6 graded into " + split.resolve("shard-1-of-2.grade") + "\n", first.out);
        Cli merged = Cli.run("grade", c.toString(), s.toString(), "--out", split.toString(), "--merge", "2");
        assertEquals(2, merged.code, merged.toString());
        assertTrue(merged.err.contains("parpe: shard 2 (students 4..6) of 2 missing in '" + split + "': run it again"),
                merged.err);
        assertFalse(Files.exists(split.resolve("report.csv")));
        Cli both = Cli.run("grade", c.toString(), s.toString(), "--out", split.toString(), "--merge", "2", "--shard", "2/2");
        assertEquals(2, both.code);
        assertTrue(both.err.contains("give one of them"), both.err);
    }

    /**
     * {@code scripts/sweep.slurm --grade} run with bash and the variables Slurm sets for each task
     * of an array numbered from 1 (docs/cluster.md, "Grading a class on a cluster"): the merge
     * gives the one-machine report.
     */
    @Test
    void theSlurmArrayScriptGradesShardsThatMergeIntoTheOneMachineReport() throws Exception {
        Path s = students();
        Path c = challenge();
        Path one = dir.resolve("one");
        assertEquals(0, Cli.run("grade", c.toString(), s.toString(), "--out", one.toString()).code);
        Path out = dir.resolve("array");
        String javaBin = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        for (int id = 2; id >= 1; id--) {
            ProcessBuilder pb = new ProcessBuilder("bash", "../scripts/sweep.slurm", "--grade", out.toString(), c.toString(),
                    s.toString()).redirectErrorStream(true).redirectOutput(dir.resolve("task.log").toFile());
            pb.environment().keySet().removeIf(k -> k.startsWith("SLURM_"));
            pb.environment().put("PARPE", javaBin + " -cp " + System.getProperty("java.class.path") + " org.parpe.cli.Main");
            pb.environment().putAll(Map.of("SLURM_ARRAY_TASK_ID", Integer.toString(id), "SLURM_ARRAY_TASK_MIN", "1",
                    "SLURM_ARRAY_TASK_COUNT", "2", "SLURM_ARRAY_TASK_MAX", "2", "SLURM_CPUS_PER_TASK", "1"));
            Process p = pb.start();
            assertTrue(p.waitFor(180, TimeUnit.SECONDS), "a shard took more than 3 minutes");
            assertEquals(0, p.exitValue(), Files.readString(dir.resolve("task.log")));
        }
        assertTrue(Files.readString(dir.resolve("task.log")).contains("runs shard 1/2 on 1 core(s)"));
        Cli merged = Cli.run("grade", c.toString(), s.toString(), "--out", out.toString(), "--merge", "2");
        assertEquals(0, merged.code, merged.toString());
        assertEquals(files(one), files(out));
        for (String f : files(one)) {
            assertArrayEquals(Files.readAllBytes(one.resolve(f)), Files.readAllBytes(out.resolve(f)), f);
        }
    }
}
