package org.parpe.gui.pose;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.model.Program;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;

/** A headless run's CSV trace (PARSL.md §11), read back: one row per tick, a column per module. */
final class Traces {
    final List<String> columns;
    final List<double[]> rows;

    private Traces(List<String> columns, List<double[]> rows) {
        this.columns = columns;
        this.rows = rows;
    }

    /** Runs {@code program} without simulator or hardware for at most {@code seconds}. */
    static Traces run(Program program, double seconds) {
        StringWriter out = new StringWriter();
        DiagnosticList diags = new DiagnosticList();
        RunOutcome o = Run.builder(program, RunOptions.defaults(), diags).duration(seconds).trace(out).build().execute();
        assertTrue(o.status() != RunOutcome.Status.ERROR, "run failed: " + o.message() + " " + diags.all());
        String[] lines = out.toString().split("\n");
        List<String> cols = Arrays.asList(lines[0].trim().split(","));
        List<double[]> rows = new ArrayList<>();
        for (int i = 1; i < lines.length; i++) {
            if (!lines[i].isBlank()) {
                rows.add(Arrays.stream(lines[i].trim().split(",")).mapToDouble(Double::parseDouble).toArray());
            }
        }
        return new Traces(cols, rows);
    }

    /** The commanded angle of module {@code id} at time {@code t} (a tick of 0.01 s). */
    double at(int id, double t) {
        int c = columns.indexOf("m" + id);
        if (c < 0) {
            fail("the trace has no column m" + id + ": " + columns);
        }
        int row = (int) Math.round(t / 0.01);
        double[] r = rows.get(row);
        assertEquals(t, r[0], 1e-6, "row " + row + " is not at t = " + t);
        return r[c];
    }
}
