package org.parpe.cli.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;

/**
 * {@code scripts/sweep.slurm} run with bash and the variables Slurm would set for each task of
 * an array: the merged shards must equal the sweep made on one machine.
 */
class SlurmArrayTest {
    private static final Path SCRIPT = Path.of("../scripts/sweep.slurm");

    @TempDir
    Path dir;

    private static String parpeCommand() {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        return java + " -cp " + System.getProperty("java.class.path") + " org.parpe.cli.Main";
    }

    private int task(Path out, Path script, Map<String, String> slurm) throws Exception {
        List<String> cmd = new ArrayList<>(List.of("bash", SCRIPT.toString(), out.toString(), script.toString(),
                "--sim", "snake:n=6", "--duration", "1", "--vary", "bend=20..40:3", "--vary", "period=1,2",
                "--param", "phase=0.2", "--seed", "9"));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(dir.resolve("task.log").toFile());
        pb.environment().keySet().removeIf(k -> k.startsWith("SLURM_"));
        pb.environment().put("PARPE", parpeCommand());
        pb.environment().putAll(slurm);
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "a shard took more than 2 minutes");
        return p.exitValue();
    }

    @Test
    void mergedArrayShardsEqualTheOneMachineSweep() throws Exception {
        assertTrue(!System.getProperty("java.class.path").contains(" "), "the class path has a space");
        Path script = SweepCommandTest.snakeIn(dir);
        Path whole = dir.resolve("whole.csv");
        Cli one = Cli.run("sweep", script.toString(), "--sim", "snake:n=6",
                "--duration", "1", "--vary", "bend=20..40:3", "--vary", "period=1,2", "--param", "phase=0.2",
                "--seed", "9", "--out", whole.toString());
        assertEquals(0, one.code, one.err);
        // An array numbered from 0 with MIN/MAX only (older Slurm), tasks in reverse order.
        Path out = dir.resolve("shards");
        for (int id = 3; id >= 0; id--) {
            int code = task(out, script, Map.of("SLURM_ARRAY_TASK_ID", Integer.toString(id),
                    "SLURM_ARRAY_TASK_MIN", "0", "SLURM_ARRAY_TASK_MAX", "3", "SLURM_CPUS_PER_TASK", "1"));
            assertEquals(0, code, Files.readString(dir.resolve("task.log")));
        }
        List<String> shards = new ArrayList<>();
        try (var files = Files.list(out)) {
            files.map(Path::toString).sorted().forEach(shards::add);
        }
        assertEquals(List.of("shard-1-of-4.csv", "shard-2-of-4.csv", "shard-3-of-4.csv", "shard-4-of-4.csv"),
                shards.stream().map(s -> Path.of(s).getFileName().toString()).toList());
        Path merged = dir.resolve("merged.csv");
        List<String> args = new ArrayList<>(List.of("merge"));
        List<String> reversed = new ArrayList<>(shards);
        java.util.Collections.reverse(reversed);
        args.addAll(reversed);
        args.addAll(List.of("--out", merged.toString()));
        Cli m = Cli.run(args.toArray(new String[0]));
        assertEquals(0, m.code, m.err);
        assertEquals(Files.readAllLines(whole), Files.readAllLines(merged));
        assertEquals(7, Files.readAllLines(merged).size());
    }

    @Test
    void anArrayNumberedFromOneWithACountUsesEveryTask() throws Exception {
        Path script = SweepCommandTest.snakeIn(dir);
        Path out = dir.resolve("shards");
        int code = task(out, script, Map.of("SLURM_ARRAY_TASK_ID", "2", "SLURM_ARRAY_TASK_MIN", "1",
                "SLURM_ARRAY_TASK_COUNT", "2"));
        assertEquals(0, code, Files.readString(dir.resolve("task.log")));
        List<String> rows = Files.readAllLines(out.resolve("shard-2-of-2.csv"));
        assertEquals(List.of("# parpe sweep shard 2/2: 3 runs from run 3 of 6", "# parpe sweep shard 2/2: complete"),
                List.of(rows.get(0), rows.get(rows.size() - 1)));
        assertEquals(6, rows.size());
        assertTrue(rows.get(2).startsWith("3,6,"), rows.get(2));
        // without Slurm's variables the script refuses to guess
        assertEquals(1, task(dir.resolve("none"), script, Map.of()));
        assertTrue(Files.readString(dir.resolve("task.log")).contains("not an array task"));
    }

    /** Issue 26, item 2: a lost shard can be run again on its own, as the merge and the docs say. */
    @Test
    void parpeShardsRerunsOneShardOfTheSplit() throws Exception {
        Path script = SweepCommandTest.snakeIn(dir);
        Path out = dir.resolve("shards");
        // sbatch --array=3 sets MIN = MAX = ID = 3 and COUNT = 1
        int code = task(out, script, Map.of("PARPE_SHARDS", "4", "SLURM_ARRAY_TASK_ID", "3", "SLURM_ARRAY_TASK_MIN", "3",
                "SLURM_ARRAY_TASK_MAX", "3", "SLURM_ARRAY_TASK_COUNT", "1"));
        assertEquals(0, code, Files.readString(dir.resolve("task.log")));
        List<String> rows = Files.readAllLines(out.resolve("shard-3-of-4.csv"));
        assertEquals("# parpe sweep shard 3/4: 1 runs from run 3 of 6", rows.get(0));
        assertEquals(0, task(out, script, Map.of("PARPE_SHARDS", "4", "SLURM_ARRAY_TASK_ID", "4")),
                Files.readString(dir.resolve("task.log")));
        assertEquals(2, task(out, script, Map.of("PARPE_SHARDS", "4", "SLURM_ARRAY_TASK_ID", "5")));
        assertTrue(Files.readString(dir.resolve("task.log")).contains("task 5 is not a shard of 4"));
    }

    /** Issue 26, items 2 and 6: arrays whose shards would not cover the sweep are refused, not run. */
    @Test
    void gappedArraysAndBareSingleTasksAreRefused() throws Exception {
        Path script = SweepCommandTest.snakeIn(dir);
        Path out = dir.resolve("shards");
        // --array=1-5:2
        assertEquals(2, task(out, script, Map.of("SLURM_ARRAY_TASK_ID", "3", "SLURM_ARRAY_TASK_MIN", "1",
                "SLURM_ARRAY_TASK_MAX", "5", "SLURM_ARRAY_TASK_COUNT", "3", "SLURM_ARRAY_TASK_STEP", "2")));
        assertTrue(Files.readString(dir.resolve("task.log")).contains("must be a step-1 range"),
                Files.readString(dir.resolve("task.log")));
        // --array=1,2,7
        assertEquals(2, task(out, script, Map.of("SLURM_ARRAY_TASK_ID", "2", "SLURM_ARRAY_TASK_MIN", "1",
                "SLURM_ARRAY_TASK_MAX", "7", "SLURM_ARRAY_TASK_COUNT", "3", "SLURM_ARRAY_TASK_STEP", "1")));
        assertTrue(Files.readString(dir.resolve("task.log")).contains("must be a step-1 range"));
        // --array=4 without PARPE_SHARDS: once the whole sweep as shard 1/1
        assertEquals(2, task(out, script, Map.of("SLURM_ARRAY_TASK_ID", "4", "SLURM_ARRAY_TASK_MIN", "4",
                "SLURM_ARRAY_TASK_MAX", "4", "SLURM_ARRAY_TASK_COUNT", "1")));
        assertTrue(Files.readString(dir.resolve("task.log")).contains("would run the whole sweep as shard 1/1"));
        assertTrue(!Files.exists(out) || Files.list(out).findAny().isEmpty(), "a refused task wrote a shard");
    }

    /** Issue 26, item 6: a folder reused with another number of shards fails at the start, not at the merge. */
    @Test
    void aFolderWithShardsOfAnotherSplitIsRefused() throws Exception {
        Path script = SweepCommandTest.snakeIn(dir);
        Path out = dir.resolve("shards");
        Files.createDirectories(out);
        Files.writeString(out.resolve("shard-1-of-8.csv"), "old\n");
        assertEquals(2, task(out, script, Map.of("SLURM_ARRAY_TASK_ID", "1", "SLURM_ARRAY_TASK_MIN", "1",
                "SLURM_ARRAY_TASK_MAX", "2")));
        assertTrue(Files.readString(dir.resolve("task.log")).contains("already holds shards of a sweep split into 8"),
                Files.readString(dir.resolve("task.log")));
        assertEquals(List.of("old"), Files.readAllLines(out.resolve("shard-1-of-8.csv")));
    }

    @Test
    void mergeRefusesAnIncompleteSetOfShards() throws Exception {
        Path a = dir.resolve("a.csv");
        Files.writeString(a, "run,runs,combination,repeat,seed,bend,duration_s\n0,3,0,0,1,5,1.0\n2,3,2,0,1,7,1.0\n");
        Cli r = Cli.run("merge", a.toString());
        assertEquals(1, r.code);
        assertEquals("parpe: runs are missing: 1 of 3 (the first is run 1); is a shard missing or unfinished?",
                r.err.strip());
        Path b = dir.resolve("b.csv");
        Files.writeString(b, "time,m0\n0,1\n");
        Cli bad = Cli.run("merge", a.toString(), b.toString());
        assertEquals(1, bad.code);
        assertTrue(bad.err.startsWith(b + ":1: error: not a sweep result"), bad.err);
        assertTrue(new File(a.toString()).exists());
    }
    /**
     * Issue 26, item 4, for the app image's launcher, which cannot read Slurm's variables:
     * sweep.slurm gives the JVM 60 % of the task's memory through JAVA_TOOL_OPTIONS, and leaves
     * a heap the user set alone.
     */
    @Test
    void theTasksHeapIsSizedFromItsMemoryForAnyLauncher() throws Exception {
        Path seen = dir.resolve("seen.txt");
        Path fake = Files.writeString(dir.resolve("fake-parpe"), "#!/bin/sh\nprintf '%s' \"$JAVA_TOOL_OPTIONS\" > " + seen + "\n");
        fake.toFile().setExecutable(true);
        Path script = SweepCommandTest.snakeIn(dir);
        Map<String, String> env = new java.util.HashMap<>(Map.of("SLURM_ARRAY_TASK_ID", "1", "SLURM_ARRAY_TASK_MIN", "1",
                "SLURM_ARRAY_TASK_MAX", "2", "SLURM_MEM_PER_NODE", "1000", "PARPE", fake.toString()));
        env.put("JAVA_TOOL_OPTIONS", "");
        assertEquals(0, task(dir.resolve("a"), script, env), Files.readString(dir.resolve("task.log")));
        assertEquals("-Xmx600m", Files.readString(seen));
        env.put("JAVA_TOOL_OPTIONS", "-Xmx2g");
        assertEquals(0, task(dir.resolve("b"), script, env), Files.readString(dir.resolve("task.log")));
        assertEquals("-Xmx2g", Files.readString(seen));
    }
}
