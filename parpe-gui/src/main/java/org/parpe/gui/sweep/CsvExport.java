package org.parpe.gui.sweep;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.SWTException;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.io.AtomicFiles;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.sweep.Axis;
import org.parpe.sim.sweep.SweepCsv;
import org.parpe.sim.sweep.SweepRow;

/**
 * "Save CSV…": the rows in the engine's CSV form ({@link SweepCsv}, the same columns as
 * {@code parpe sweep --out}), written by the output rules ({@link AtomicFiles}),
 * so that a failed write never leaves half a file.
 */
final class CsvExport {
    private CsvExport() {
    }

    /** The header's parameter columns for {@code names} (the CSV shows only their names). */
    static List<Axis> axes(List<String> names) {
        List<Axis> axes = new ArrayList<>();
        for (String n : names) {
            axes.add(Axis.continuous(n, 0, 0));
        }
        return axes;
    }

    /** Writes {@code rows} (of a sweep of {@code runs} runs over {@code axes}) to {@code file}. */
    static void write(Path file, List<Axis> axes, List<SweepRow> rows, int runs, boolean scored) throws IOException {
        AtomicFiles.write(file, out -> {
            BufferedWriter w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8));
            w.write(SweepCsv.header(axes, scored));
            w.write('\n');
            for (SweepRow r : rows) {
                w.write(SweepCsv.line(r, runs, scored));
                w.write('\n');
            }
            w.flush();
        });
    }

    /**
     * Writes the header for {@code axes} and then the CSV lines in {@code lines} (the rows
     * {@link Results} did not keep went to its temporary file as they came) to {@code file}.
     */
    static void write(Path file, List<Axis> axes, Results.Spill lines, boolean scored) throws IOException {
        AtomicFiles.write(file, out -> {
            out.write((SweepCsv.header(axes, scored) + "\n").getBytes(StandardCharsets.UTF_8));
            lines.copyTo(out);
        });
    }

    /** What became of a save: whether it worked, and a line to show. */
    interface Outcome {
        void done(boolean ok, String message);
    }

    /**
     * Writes the rows of {@code results} (read here, on the UI thread) to {@code file} on a thread of
     * its own; {@code outcome} is told on the UI thread of {@code display}.
     */
    static void inBackground(Display display, Path file, Results results, int runs, Outcome outcome) {
        List<SweepRow> kept = results.complete() ? List.copyOf(results.rows()) : List.of();
        int count = results.count();
        Results.Spill spill;
        try {
            spill = results.complete() ? null : results.spill();
        } catch (IOException e) {
            outcome.done(false, ToolMsg.SWEEP_CANNOT_SAVE.text(file, e.getMessage()));
            return;
        }
        if (!results.complete() && spill == null) {
            outcome.done(false, ToolMsg.SWEEP_CANNOT_SAVE.text(file, results.spillError()));
            return;
        }
        List<Axis> axes = axes(results.parameters());
        boolean scored = results.scored();
        Thread t = new Thread(() -> {
            boolean ok;
            String said;
            try (Results.Spill lines = spill) {
                if (lines != null) {
                    write(file, axes, lines, scored);
                } else {
                    write(file, axes, kept, runs, scored);
                }
                ok = true;
                said = ToolMsg.SWEEP_SAVED_ROWS.text(count, file);
            } catch (IOException | RuntimeException e) {
                ok = false;
                said = ToolMsg.SWEEP_CANNOT_SAVE.text(file, e.getMessage());
            }
            boolean saved = ok;
            String text = said;
            try {
                display.asyncExec(() -> outcome.done(saved, text));
            } catch (SWTException closed) {
                // The IDE closed during the save: nobody is left to tell.
            }
        }, "parpe-sweep-csv");
        t.setDaemon(true);
        t.start();
    }
}
