package org.parpe.sim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.Message;

class SweepTest {
    private static final double DURATION = 1.5;

    private static Sweep grid() throws SweepException {
        Evaluator ev = Scripts.snake(DURATION, Map.of("phase", 0.2));
        return new Sweep(ev, SweepSpec.grid(List.of(VarySpec.parse("bend=20..40:3", ev.parameters()),
                VarySpec.parse("period=1,2", ev.parameters())), 1, 7));
    }

    /** The CSV lines of runs {@code [from, to)} on {@code jobs} threads, as the listener received them. */
    private static List<String> csv(Sweep sweep, int from, int to, int jobs) {
        List<String> lines = new ArrayList<>();
        SweepResult r = sweep.run(from, to, jobs, new SweepListener() {
            @Override
            public void row(SweepRow row) {
                lines.add(SweepCsv.line(row, sweep.spec().size()));
            }
        }, new Cancellation());
        assertFalse(r.cancelled());
        assertEquals(lines, r.rows().stream().map(row -> SweepCsv.line(row, sweep.spec().size())).toList());
        return lines;
    }

    @Test
    void gridRunsEveryCombinationInOrderFirstAxisSlowest() throws Exception {
        Sweep sweep = grid();
        assertEquals(6, sweep.spec().size());
        List<Map<String, Double>> values = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            values.add(sweep.spec().point(i).values());
        }
        assertEquals(List.of(Map.of("bend", 20.0, "period", 1.0), Map.of("bend", 20.0, "period", 2.0),
                Map.of("bend", 30.0, "period", 1.0), Map.of("bend", 30.0, "period", 2.0),
                Map.of("bend", 40.0, "period", 1.0), Map.of("bend", 40.0, "period", 2.0)), values);
    }

    @Test
    void sameSpecGivesTheSameCsvWhateverTheThreads() throws Exception {
        List<String> once = csv(grid(), 0, 6, 1);
        List<String> again = csv(grid(), 0, 6, 2);
        assertEquals(once, again);
        assertEquals(6, once.size());
        // the runs differ from each other: the values reach the simulation
        assertEquals(6, once.stream().map(l -> l.split(",")[8]).distinct().count());
        assertTrue(once.get(0).startsWith("0,6,0,0,7,20,1,1.500000,"), once.get(0));
    }

    @Test
    void readingTheCsvGivesRowsThatPrintTheSameLines() throws Exception {
        Sweep sweep = grid();
        List<String> lines = new ArrayList<>();
        lines.add(SweepCsv.header(sweep.spec().axes()));
        lines.addAll(csv(sweep, 0, 6, 1));
        // a run that could not start: empty measurements, an error with a comma and a quote
        lines.add("6,7,6,0,7,50,2,,,,,,,,0,\"bend 50 > max, \"\"60\"\"\"");
        SweepResult read = SweepCsv.read(lines);
        assertEquals(lines.subList(1, 7), read.rows().subList(0, 6).stream().map(r -> SweepCsv.line(r, 6)).toList());
        SweepRow failed = read.rows().get(6);
        assertEquals("bend 50 > max, \"60\"", failed.error().toString());
        assertTrue(Double.isNaN(failed.forwardSpeed()) && !failed.ok());
        assertEquals(lines.get(7), SweepCsv.line(failed, 7));
        assertThrows(SweepException.class, () -> SweepCsv.read(List.of(lines.get(0), "0,6,0,0,7,20")));
    }

    /**
     * Issue 32 item 6: a row's error is a message, shown in the user's language where it is shown
     * (the IDE's results table), while the CSV file holds it in English whatever the language (a
     * file for scripts, merged from shards of machines in other languages). Before, the row held
     * the text preformatted in the language of the run, and the file held that.
     */
    @Test
    void aRowsErrorIsShownInTheUsersLanguageAndWrittenInEnglish() throws Exception {
        Evaluator ev = Scripts.snake(0.1, Map.of());
        org.parpe.core.text.Lang.use(java.util.Locale.GERMAN);
        try {
            SweepRow row = ev.run(new Point(0, 0, 0, Map.of("bend", 90.0), 1), new Cancellation());
            assertFalse(row.ok());
            assertTrue(row.error().toString().endsWith(": error: Parameter 'bend' muss <= 60 sein, ist aber 90"),
                    row.error().toString());
            assertTrue(SweepCsv.line(row, 1).endsWith(": error: parameter 'bend' must be <= 60, got 90\""),
                    SweepCsv.line(row, 1));
        } finally {
            org.parpe.core.text.Lang.use(java.util.Locale.ENGLISH);
        }
    }

    /** A sweep in a world has a last {@code score} column after the quoted error: it reads back too (merge --plot). */
    @Test
    void aScoredCsvReadsBackWithItsScores() throws Exception {
        Point p = new Point(0, 0, 0, Map.of("bend", 20.0), 7);
        SweepRow ok = new SweepRow(p, 5, 1, 0.9, 0.18, 0.2, 12, 300, false, Message.EMPTY, 42.5);
        SweepRow failed = new SweepRow(new Point(1, 1, 0, Map.of("bend", 50.0), 7), Double.NaN, Double.NaN, Double.NaN,
                Double.NaN, Double.NaN, Double.NaN, Double.NaN, false, Message.verbatim("bend 50 > max, \"60\""), Double.NaN);
        List<String> lines = List.of(SweepCsv.header(List.of(Axis.list("bend", List.of(20.0, 50.0))), true),
                SweepCsv.line(ok, 2, true), SweepCsv.line(failed, 2, true));
        assertTrue(lines.get(0).endsWith(",error,score"), lines.get(0));
        SweepResult read = SweepCsv.read(lines);
        assertEquals(42.5, read.rows().get(0).score());
        assertEquals("bend 50 > max, \"60\"", read.rows().get(1).error().toString());
        assertEquals(lines.subList(1, 3), read.rows().stream().map(r -> SweepCsv.line(r, 2, true)).toList());
    }

    /** Issue 26, item 3: a shard's framing lines are checked and dropped; an unfinished shard is named. */
    @Test
    void framedShardsMergeAndAnUnfinishedOneIsNamed() throws Exception {
        Sweep sweep = grid();
        List<String> whole = csv(sweep, 0, 6, 2);
        Map<String, List<String>> shards = new LinkedHashMap<>();
        for (int k = 1; k <= 2; k++) {
            int[] range = SweepSpec.shard(6, k, 2);
            List<String> lines = new ArrayList<>();
            lines.add(SweepCsv.shardStart(k, 2, range[0], range[1], 6));
            lines.add(SweepCsv.header(sweep.spec().axes()));
            lines.addAll(whole.subList(range[0], range[1]));
            lines.add(SweepCsv.shardEnd(k, 2));
            shards.put("s" + k, lines);
        }
        List<String> expected = new ArrayList<>();
        expected.add(SweepCsv.header(sweep.spec().axes()));
        expected.addAll(whole);
        assertEquals(expected, SweepCsv.merge(shards));
        List<String> cut = new ArrayList<>(shards.get("s2").subList(0, 3)); // the task stopped after one run
        shards.put("s2", cut);
        IncompleteSweepException e = assertThrows(IncompleteSweepException.class, () -> SweepCsv.merge(shards));
        assertEquals("s2: error: shard 2/2 is unfinished: it holds 1 of its 3 runs (runs 3..5); its task was stopped"
                + " or killed before the end", e.getMessage());
        assertEquals(List.of(2), e.rerun());
        assertEquals(2, e.of());
        shards.remove("s2");
        assertEquals("error: shard 2/2 is missing (runs 3..5)",
                assertThrows(IncompleteSweepException.class, () -> SweepCsv.merge(shards)).getMessage());
    }

    @Test
    void shardsTogetherAreTheWholeSweep() throws Exception {
        Sweep sweep = grid();
        List<String> whole = csv(sweep, 0, 6, 2);
        Map<String, List<String>> shards = new LinkedHashMap<>();
        for (int k = 3; k >= 1; k--) {
            int[] range = SweepSpec.shard(6, k, 3);
            List<String> lines = new ArrayList<>();
            lines.add(SweepCsv.header(sweep.spec().axes()));
            lines.addAll(csv(grid(), range[0], range[1], 1));
            shards.put("shard" + k + ".csv", lines);
        }
        List<String> expected = new ArrayList<>();
        expected.add(SweepCsv.header(sweep.spec().axes()));
        expected.addAll(whole);
        assertEquals(expected, SweepCsv.merge(shards));
    }

    @Test
    void shardsCoverEveryRunOnce() {
        int covered = 0;
        for (int k = 1; k <= 7; k++) {
            int[] r = SweepSpec.shard(20, k, 7);
            assertEquals(covered, r[0]);
            assertTrue(r[1] - r[0] == 2 || r[1] - r[0] == 3);
            covered = r[1];
        }
        assertEquals(20, covered);
    }

    @Test
    void mergeRefusesMissingAndDoubledRuns() throws Exception {
        String header = "run,runs,combination,repeat,seed,bend,duration_s";
        SweepException missing = assertThrows(SweepException.class, () -> SweepCsv.merge(Map.of(
                "a.csv", List.of(header, "0,3,0,0,1,5,1.0", "2,3,2,0,1,7,1.0"))));
        assertEquals("runs are missing: 1 of 3 (the first is run 1); is a shard missing or unfinished?",
                missing.getMessage());
        Map<String, List<String>> twice = new LinkedHashMap<>();
        twice.put("a.csv", List.of(header, "0,2,0,0,1,5,1.0"));
        twice.put("b.csv", List.of(header, "0,2,0,0,1,5,1.0", "1,2,1,0,1,6,1.0"));
        SweepException doubled = assertThrows(SweepException.class, () -> SweepCsv.merge(twice));
        assertEquals("b.csv:2: error: run 0 is also in a.csv; were shards given twice or run with different"
                + " --shard N?", doubled.getMessage());
    }

    @Test
    void randomSweepsDependOnTheSeedOnly() throws Exception {
        Evaluator ev = Scripts.snake(DURATION, Map.of());
        List<Axis> space = SweepSpec.declaredSpace(ev.parameters(), java.util.Set.of());
        assertEquals(List.of("bend", "period", "phase"), space.stream().map(Axis::name).toList());
        SweepSpec a = SweepSpec.random(space, 4, 1, 11);
        SweepSpec b = SweepSpec.random(space, 4, 1, 11);
        SweepSpec c = SweepSpec.random(space, 4, 1, 12);
        for (int i = 0; i < 4; i++) {
            assertEquals(a.point(i), b.point(i));
            assertNotEquals(a.point(i).values(), c.point(i).values());
            double bend = a.point(i).values().get("bend");
            assertEquals(Math.rint(bend), bend);
        }
    }

    @Test
    void cancellingStopsTheSweep() throws Exception {
        Cancellation stop = new Cancellation();
        List<SweepRow> seen = new ArrayList<>();
        SweepResult r = grid().run(0, 6, 1, new SweepListener() {
            @Override
            public void row(SweepRow row) {
                seen.add(row);
                stop.cancel();
            }
        }, stop);
        assertTrue(r.cancelled());
        assertEquals(1, r.rows().size());
        assertEquals(seen, r.rows());
    }

    /**
     * A caller that keeps what it needs itself (the IDE's dialog, issue 23 item 13) asks the sweep
     * not to keep the rows: the listener gets the same rows in the same order, the result holds none.
     */
    @Test
    void aSweepThatDoesNotKeepItsRowsHandsTheListenerTheSameRows() throws Exception {
        List<String> kept = csv(grid(), 0, 6, 2);
        Sweep sweep = grid();
        List<String> streamed = new ArrayList<>();
        SweepResult r = sweep.run(0, 6, 2, new SweepListener() {
            @Override
            public void row(SweepRow row) {
                streamed.add(SweepCsv.line(row, sweep.spec().size()));
            }
        }, new Cancellation(), false);
        assertEquals(kept, streamed);
        assertEquals(List.of(), r.rows());
        assertFalse(r.cancelled(), "every run was handed over");
    }

    /**
     * Issue 31 item 5: framed shards are merged as streams, so their rows must be their runs in
     * order, as sweep writes them; an edited shard is named at the line.
     */
    @Test
    void aFramedShardWithRowsOutOfOrderOrMissingIsNamed() throws Exception {
        String header = "run,runs,combination,repeat,seed,bend,duration_s";
        Map<String, List<String>> shards = new LinkedHashMap<>();
        shards.put("s1", List.of(SweepCsv.shardStart(1, 1, 0, 3, 3), header, "0,3,0,0,1,5,1.0", "2,3,2,0,1,7,1.0",
                "1,3,1,0,1,6,1.0", SweepCsv.shardEnd(1, 1)));
        assertEquals("s1:4: error: run 2 where run 1 belongs; a shard's rows are its runs in order, each once (was the"
                + " file edited?)", assertThrows(SweepException.class, () -> SweepCsv.merge(shards)).getMessage());
        shards.put("s1", List.of(SweepCsv.shardStart(1, 1, 0, 3, 3), header, "0,3,0,0,1,5,1.0", "1,3,1,0,1,6,1.0",
                SweepCsv.shardEnd(1, 1)));
        assertEquals("s1: error: shard 1/1 holds 2 of its 3 runs (runs 0..2) but is marked complete (was the file"
                + " edited?); run it again", assertThrows(SweepException.class, () -> SweepCsv.merge(shards)).getMessage());
    }
}
