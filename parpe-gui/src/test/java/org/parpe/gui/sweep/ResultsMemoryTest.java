package org.parpe.gui.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.text.Message;
import org.parpe.sim.sweep.Constraints;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.Point;
import org.parpe.sim.sweep.SweepCsv;
import org.parpe.sim.sweep.SweepResult;
import org.parpe.sim.sweep.SweepRow;

/**
 * Issue 23, item 13: 1 024 jobs with a million random runs took the IDE to 3.4 GB; the dialog
 * kept every row (and the engine kept them all again). Now the table and the plot keep a bounded
 * number of rows, the best and the counts are kept as rows come, and every row reaches Save CSV…
 * through a temporary file.
 */
class ResultsMemoryTest {
    private static final int RUNS = 1000;

    @TempDir
    Path dir;

    private static SweepRow row(int i) {
        Point p = new Point(i, i, 0, Map.of("amp", (double) i), 0L);
        boolean fell = i % 10 == 3;
        Message error = i % 97 == 5 ? Message.verbatim("boom, \"quoted\"") : Message.EMPTY;
        double speed = i == 700 ? 1.0 : (i % 13) / 100.0;
        return new SweepRow(p, 1, speed, speed, speed, speed, fell ? 95 : 5, 10, fell, error);
    }

    @Test
    void keepsABoundedNumberOfRowsYetFindsTheBestAndSavesEveryRow() throws Exception {
        Results r = new Results(dir.resolve("s.xml"), Results.Mode.SWEEP, List.of("amp"), Map.of("amp", 0.0),
                Objective.FORWARD_SPEED, Constraints.NONE, 100, RUNS);
        List<SweepRow> all = new ArrayList<>();
        for (int i = 0; i < RUNS; i++) {
            SweepRow row = row(i);
            all.add(row);
            r.add(row);
        }
        assertEquals(100, r.rows().size(), "the table and the plot keep the first rows only");
        assertEquals(all.subList(0, 100), r.rows());
        assertEquals(RUNS, r.count());
        assertEquals(SweepResult.best(all, Objective.FORWARD_SPEED, SweepResult.STANDING).orElseThrow(), r.best());
        assertEquals(700, r.number(r.best()), "the best is found among the rows not kept too");
        assertEquals(all.stream().filter(x -> !x.ok()).count(), r.failed());
        assertEquals(all.stream().filter(x -> x.ok() && x.fell()).count(), r.fell());
        assertTrue(!r.complete());
        Path csv = dir.resolve("all.csv");
        try (Results.Spill spill = r.spill()) {
            CsvExport.write(csv, CsvExport.axes(List.of("amp")), spill, false);
        }
        List<String> lines = Files.readAllLines(csv);
        List<String> expected = new ArrayList<>();
        expected.add(SweepCsv.header(CsvExport.axes(List.of("amp"))));
        for (SweepRow x : all) {
            expected.addAll(SweepCsv.line(x, RUNS).lines().toList());
        }
        assertEquals(expected, lines, "Save CSV\u2026 writes every row, as parpe sweep --out would");
        Path spill = r.spillFile();
        r.discard();
        assertTrue(!Files.exists(spill), "the temporary file is deleted");
    }

    private static Results filled(Path dir, int rows) {
        Results r = new Results(dir.resolve("s.xml"), Results.Mode.SWEEP, List.of("amp"), Map.of("amp", 0.0),
                Objective.FORWARD_SPEED, Constraints.NONE, 100, RUNS);
        for (int i = 0; i < rows; i++) {
            r.add(row(i));
        }
        return r;
    }

    private static List<String> expected(int rows) {
        List<String> lines = new ArrayList<>();
        lines.add(SweepCsv.header(CsvExport.axes(List.of("amp"))));
        for (int i = 0; i < rows; i++) {
            lines.addAll(SweepCsv.line(row(i), RUNS).lines().toList());
        }
        return lines;
    }

    /**
     * Save CSV… during a sweep writes the rows that had come when it was chosen, whole lines only,
     * although the sweep goes on writing the temporary file while the save copies it (it used to
     * copy to the file's end, which could stop in the middle of a line).
     */
    @Test
    void aSaveDuringASweepWritesTheRowsThatHadComeAndNoHalfLine() throws Exception {
        Results r = filled(dir, 300);
        try (Results.Spill s = r.spill()) {
            for (int i = 300; i < RUNS; i++) {
                r.add(row(i));
            }
            Path csv = dir.resolve("during.csv");
            CsvExport.write(csv, CsvExport.axes(List.of("amp")), s, false);
            List<String> saved = Files.readAllLines(csv);
            assertEquals(301, saved.size(), "the header and the 300 rows that had come");
            assertEquals(expected(300), saved);
        }
    }

    /**
     * A new sweep started (or the dialog closed) while Save CSV… is still writing deletes the old
     * temporary file; the save still writes every row it was asked for (it used to fail with
     * "no such file").
     */
    @Test
    void aSaveOutlivesTheSweepThatStartedIt() throws Exception {
        Results r = filled(dir, 500);
        try (Results.Spill s = r.spill()) {
            r.discard();
            Path csv = dir.resolve("after.csv");
            CsvExport.write(csv, CsvExport.axes(List.of("amp")), s, false);
            assertEquals(expected(500), Files.readAllLines(csv));
        }
    }

    @Test
    void aSmallSweepKeepsEveryRowAndNeedsNoTemporaryFile() {
        Results r = new Results(dir.resolve("s.xml"), Results.Mode.SWEEP, List.of("amp"), Map.of("amp", 0.0),
                Objective.FORWARD_SPEED, Constraints.NONE, Results.KEEP, 50);
        for (int i = 0; i < 50; i++) {
            r.add(row(i));
        }
        assertTrue(r.complete());
        assertEquals(50, r.rows().size());
        assertNull(r.spillFile());
        assertNotNull(r.best());
    }
}
