package org.parpe.cli.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;

/**
 * Issue 26, item 3: a shard whose task is stopped (Slurm's SIGTERM at scancel or at the time
 * limit) or killed (SIGKILL: memory limit, lost node) never passes for a whole shard, keeps the
 * rows it finished in a visible {@code .partial} file, and {@code parpe merge} names the shard to
 * run again and where its rows are. Shards run as processes of their own, as on a cluster.
 */
class ShardFileTest {
    @TempDir
    Path dir;

    private Path script() throws Exception {
        return Files.exists(dir.resolve("snake.xml")) ? dir.resolve("snake.xml") : SweepCommandTest.snakeIn(dir);
    }

    /** {@code parpe sweep} of 6 runs as shard K/3 in a process of its own, stderr to a log. */
    private Process shard(int k, String duration, Path log) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(java, "-cp", System.getProperty("java.class.path"),
                "org.parpe.cli.Main", "sweep", script().toString(), "--sim", "snake:n=6", "--duration", duration,
                "--vary", "bend=20..40:3", "--vary", "period=1,2", "--param", "phase=0.2", "--seed", "9",
                "--jobs", "1", "--shard", k + "/3", "--out", dir.resolve("shard-" + k + ".csv").toString()));
        return new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
    }

    /** Waits until {@code file} holds at least {@code lines} lines (the process keeps writing). */
    private static void awaitLines(Path file, int lines, Process p) throws Exception {
        for (int i = 0; i < 1200; i++) {
            if (Files.exists(file) && Files.readAllLines(file).size() >= lines) {
                return;
            }
            assertTrue(p.isAlive(), "the shard ended before writing " + lines + " lines");
            Thread.sleep(50);
        }
        throw new AssertionError(file + " never got " + lines + " lines");
    }

    private List<String> hiddenOrTemporary() throws Exception {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(f -> f.getFileName().toString()).filter(n -> n.startsWith(".") || n.endsWith(".tmp")).toList();
        }
    }

    @Test
    void sigtermKeepsTheFinishedRowsAsPartialAndSaysSigterm() throws Exception {
        Path log = dir.resolve("term.log");
        Process p = shard(2, "30", log);
        Path partial = dir.resolve("shard-2.csv.partial");
        awaitLines(partial, 3, p); // framing line, header, one run
        p.destroy(); // SIGTERM, as Slurm sends it
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        String err = Files.readString(log);
        assertEquals(143, p.exitValue(), err);
        assertTrue(err.contains("parpe: stopped by SIGTERM"), err);
        assertFalse(err.contains("Ctrl-C"), err);
        assertTrue(err.contains("shard 2/3 is unfinished"), err);
        assertFalse(Files.exists(dir.resolve("shard-2.csv")), "a stopped shard looks whole");
        List<String> rows = Files.readAllLines(partial);
        assertEquals("# parpe sweep shard 2/3: 2 runs from run 2 of 6", rows.get(0));
        assertTrue(rows.get(2).startsWith("2,6,"), rows.toString());
        assertFalse(rows.get(rows.size() - 1).endsWith("complete"), rows.toString());
        assertEquals(List.of(), hiddenOrTemporary());
    }

    @Test
    void sigkillKeepsTheFinishedRowsAndNoHiddenFile() throws Exception {
        Process p = shard(1, "30", dir.resolve("kill.log"));
        Path partial = dir.resolve("shard-1.csv.partial");
        awaitLines(partial, 3, p);
        p.destroyForcibly(); // SIGKILL: no shutdown hook runs
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertFalse(Files.exists(dir.resolve("shard-1.csv")));
        List<String> rows = Files.readAllLines(partial);
        assertTrue(rows.size() >= 3 && rows.get(2).startsWith("0,6,"), rows.toString());
        assertEquals(List.of(), hiddenOrTemporary());
    }

    @Test
    void mergeNamesTheShardToRerunAndWhereItsRowsAre() throws Exception {
        for (int k : new int[] {1, 3}) {
            Process p = shard(k, "1", dir.resolve("s" + k + ".log"));
            assertTrue(p.waitFor(120, TimeUnit.SECONDS));
            assertEquals(0, p.exitValue(), Files.readString(dir.resolve("s" + k + ".log")));
        }
        // what a task killed after one run leaves: the framing line, the header and one row
        Process p = shard(2, "30", dir.resolve("s2.log"));
        Path partial = dir.resolve("shard-2.csv.partial");
        awaitLines(partial, 3, p);
        p.destroyForcibly();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        Path merged = dir.resolve("all.csv");
        Cli m = Cli.run("merge", dir.resolve("shard-1.csv").toString(), dir.resolve("shard-3.csv").toString(),
                "--out", merged.toString());
        assertEquals(1, m.code, m.err);
        assertTrue(m.err.contains("parpe: shard 2/3 is missing (runs 2..3)"), m.err);
        assertTrue(m.err.contains(partial + " holds what shard 2/3 finished"), m.err);
        assertTrue(m.err.contains("rerun shard 2 of 3 ") && m.err.contains("PARPE_SHARDS=3 sbatch --array=2 "), m.err);
        assertFalse(Files.exists(merged));
        // the unfinished file given too: it is named as unfinished, with what it holds
        Cli u = Cli.run("merge", dir.resolve("shard-1.csv").toString(), partial.toString(),
                dir.resolve("shard-3.csv").toString());
        assertEquals(1, u.code);
        assertTrue(u.err.startsWith(partial + ": error: shard 2/3 is unfinished: it holds "), u.err);
        assertTrue(u.err.contains(" of its 2 runs (runs 2..3)"), u.err);
    }

    @Test
    void shardsOfAnotherSplitAreNamed() throws Exception {
        Path a = dir.resolve("a.csv");
        Path b = dir.resolve("b.csv");
        String header = "run,runs,combination,repeat,seed,bend,duration_s\n";
        Files.writeString(a, "# parpe sweep shard 1/2: 2 runs from run 0 of 4\n" + header
                + "0,4,0,0,1,5,1.0\n1,4,1,0,1,6,1.0\n# parpe sweep shard 1/2: complete\n");
        Files.writeString(b, "# parpe sweep shard 2/4: 1 runs from run 1 of 4\n" + header
                + "1,4,1,0,1,6,1.0\n# parpe sweep shard 2/4: complete\n");
        Cli m = Cli.run("merge", a.toString(), b.toString());
        assertEquals(1, m.code);
        assertTrue(m.err.startsWith(b + ":1: error: shard 2/4 of a sweep of 4 runs, but " + a
                + " is shard 1/2 of a sweep of 4 runs; merge the files of one split only"), m.err);
    }

    @Test
    void mergeDrawsThePlotAndWritesTheOneMachineFile() throws Exception {
        Path whole = dir.resolve("whole.csv");
        Cli one = Cli.run("sweep", script().toString(), "--sim", "snake:n=6", "--duration", "1", "--vary",
                "bend=20..40:3", "--vary", "period=1,2", "--param", "phase=0.2", "--seed", "9", "--out",
                whole.toString(), "--plot", dir.resolve("whole.png").toString());
        assertEquals(0, one.code, one.err);
        List<String> args = new ArrayList<>(List.of("merge"));
        for (int k = 3; k >= 1; k--) {
            Path log = dir.resolve("s" + k + ".log");
            Process p = shard(k, "1", log);
            assertTrue(p.waitFor(120, TimeUnit.SECONDS));
            assertEquals(0, p.exitValue(), Files.readString(log));
            // progress reaches a log (standard error is not a terminal) as whole lines
            assertTrue(Files.readString(log).contains("parpe: 2/2 runs, "), Files.readString(log));
            args.add(dir.resolve("shard-" + k + ".csv").toString());
        }
        Path merged = dir.resolve("all.csv");
        Path png = dir.resolve("all.png");
        args.addAll(List.of("--out", merged.toString(), "--plot", png.toString()));
        Cli m = Cli.run(args);
        assertEquals(0, m.code, m.err);
        assertEquals(Files.readString(whole), Files.readString(merged));
        byte[] head = Files.readAllBytes(png);
        assertEquals("PNG", new String(head, 1, 3, java.nio.charset.StandardCharsets.US_ASCII));
        assertEquals(javax.imageio.ImageIO.read(dir.resolve("whole.png").toFile()).getHeight(),
                javax.imageio.ImageIO.read(png.toFile()).getHeight());
    }
    /**
     * Issue 18 (the output policy) for shards: a shard named through a link is written through
     * it (the link stays, its file gets the rows and keeps its mode), and a link planted at the
     * {@code .partial} name is refused, never followed.
     */
    @Test
    void aShardIsPutInPlaceByTheOutputPolicy() throws Exception {
        Path elsewhere = Files.createDirectory(dir.resolve("results"));
        Path real = Files.writeString(elsewhere.resolve("shard-1.csv"), "old\n");
        Files.setPosixFilePermissions(real, java.nio.file.attribute.PosixFilePermissions.fromString("rw-rw-r--"));
        Files.createSymbolicLink(dir.resolve("shard-1.csv"), real);
        Process p = shard(1, "0.2", dir.resolve("one.log"));
        assertTrue(p.waitFor(120, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), Files.readString(dir.resolve("one.log")));
        assertTrue(Files.isSymbolicLink(dir.resolve("shard-1.csv")), "the link was replaced by a file");
        List<String> rows = Files.readAllLines(real);
        assertTrue(rows.get(rows.size() - 1).endsWith("complete"), rows.toString());
        assertEquals("rw-rw-r--", java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(real)));

        // looks like an unfinished shard, so only the refusal to follow a link protects it
        String shardLike = "# parpe sweep shard 3/3: 2 runs from run 4 of 6\nkeep me\n";
        Path victim = Files.writeString(dir.resolve("victim.txt"), shardLike);
        Files.createSymbolicLink(dir.resolve("shard-3.csv.partial"), victim);
        Process q = shard(3, "0.2", dir.resolve("three.log"));
        assertTrue(q.waitFor(120, TimeUnit.SECONDS));
        assertTrue(q.exitValue() != 0, Files.readString(dir.resolve("three.log")));
        assertEquals(shardLike, Files.readString(victim));
        assertFalse(Files.exists(dir.resolve("shard-3.csv")));
    }

    /**
     * Issue 31 item 5: two sweeps given one shard's {@code --out} at once both wrote its
     * {@code .partial}, and the loser's message was only a path. The second is refused at once,
     * while the first (a process of its own, as on a cluster) keeps its rows; after the first
     * one is gone (SIGKILL: its lock goes with it), the shard can be run again.
     */
    @Test
    void aSecondSweepWritingTheSameShardIsRefusedWhileTheFirstRuns() throws Exception {
        Process p = shard(1, "30", dir.resolve("first.log"));
        Path partial = dir.resolve("shard-1.csv.partial");
        awaitLines(partial, 3, p);
        List<String> args = List.of("sweep", script().toString(), "--sim", "snake:n=6", "--duration", "0.1",
                "--vary", "bend=20..40:3", "--vary", "period=1,2", "--param", "phase=0.2", "--seed", "9",
                "--jobs", "1", "--shard", "1/3", "--out", dir.resolve("shard-1.csv").toString());
        Cli second = Cli.run(args);
        assertEquals(2, second.code, second.toString());
        assertEquals("parpe: cannot write --out file '" + dir.resolve("shard-1.csv") + "': another parpe sweep is"
                + " writing this shard now (" + partial + " is locked by it); wait for it to end, or give this one"
                + " another --out\n", second.err);
        List<String> rows = Files.readAllLines(partial);
        assertTrue(rows.size() >= 3 && rows.get(2).startsWith("0,6,"), rows.toString());
        assertTrue(p.isAlive());
        p.destroyForcibly();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        Cli again = Cli.run(args);
        assertEquals(0, again.code, again.toString());
        assertTrue(Files.readString(dir.resolve("shard-1.csv")).endsWith("# parpe sweep shard 1/3: complete\n"));
        assertFalse(Files.exists(partial));
    }

    /**
     * Issue 31 item 5: merge refused a shard over the 16 MiB input limit (about 160 000 runs),
     * though sweep writes shards of up to 10 million runs. Shards are PARPE's own output and are
     * streamed; the limit stays for other files.
     */
    @Test
    void aShardOverTheInputLimitIsMerged() throws Exception {
        String header = "run,runs,combination,repeat,seed,bend,duration_s,distance_m,forward_m,forward_speed_mps,"
                + "speed_mps,max_tilt_deg,joint_travel_deg,fell,error";
        int runs = 360_000;
        int[] first = org.parpe.sim.sweep.SweepSpec.shard(runs, 1, 2);
        Path big = dir.resolve("shard-1.csv");
        Path small = dir.resolve("shard-2.csv");
        for (int k = 1; k <= 2; k++) {
            int[] r = org.parpe.sim.sweep.SweepSpec.shard(runs, k, 2);
            try (var w = Files.newBufferedWriter(k == 1 ? big : small)) {
                w.write(org.parpe.sim.sweep.SweepCsv.shardStart(k, 2, r[0], r[1], runs) + "\n" + header + "\n");
                for (int run = r[0]; run < r[1]; run++) {
                    w.write(run + "," + runs + "," + run + ",0,7,20,10.000000,0.123456,0.120000,0.012000,0.012345,"
                            + "12.345678,1234.567890,0,\n");
                }
                w.write(org.parpe.sim.sweep.SweepCsv.shardEnd(k, 2) + "\n");
            }
        }
        assertTrue(Files.size(big) > org.parpe.core.xml.InputFiles.MAX_BYTES, Files.size(big) + " bytes");
        Path merged = dir.resolve("merged.csv");
        Cli m = Cli.run("merge", small.toString(), big.toString(), "--out", merged.toString());
        assertEquals(0, m.code, m.toString());
        assertEquals("parpe: merged " + runs + " runs from 2 files\n", m.err);
        try (var lines = Files.lines(merged)) {
            var it = lines.iterator();
            assertEquals(header, it.next());
            for (int run = 0; run < runs; run++) {
                assertTrue(it.next().startsWith(run + "," + runs + ","), "run " + run);
            }
            assertFalse(it.hasNext());
        }
        assertEquals(first[1], Files.readAllLines(big).size() - 3);
        Path plain = Files.writeString(dir.resolve("plain.csv"), header + "\n");
        Files.write(plain, new byte[(int) org.parpe.core.xml.InputFiles.MAX_BYTES], java.nio.file.StandardOpenOption.APPEND);
        Cli refused = Cli.run("merge", plain.toString(), "--out", dir.resolve("m2.csv").toString());
        assertEquals(2, refused.code, refused.toString());
        assertTrue(refused.err.startsWith("parpe: cannot read '" + plain + "': it is "), refused.err);
        assertTrue(refused.err.endsWith(" bytes, larger than the limit of 16 MiB for an input file\n"), refused.err);
    }
}
