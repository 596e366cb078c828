package org.parpe.gui.diagram;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.parpe.core.model.Program;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.gui.run.LiveStates;
import org.parpe.gui.text.PanelMsg;

/**
 * A recorded trace ({@code parpe run --trace}, docs/cli.md "Trace") made scrubbable: the trace
 * has the time and each module's commanded angle per tick, not the states, so the script's own
 * engine runs once, headless, over the trace's ticks at the trace's tick and keeps which state
 * each module is in at each one; a tick of the trace then gives the same {@link LiveStates.Frame}
 * the live overlay draws. Where the engine's angles differ from the trace's (a run with controls,
 * sensors or a stimulus file, or another script) the first such time is told: from there the
 * states shown are the script's, not the run's.
 */
final class TraceScrubber {
    private final Path file;
    private final double[] time;
    private final int[] entry;
    private final int[][] instance;
    private final int[][] state;
    private final double[][] progress;
    private final int[] ids;
    private final double differsFrom;

    private TraceScrubber(Path file, double[] time, int[] entry, int[][] instance, int[][] state, double[][] progress,
                          int[] ids, double differsFrom) {
        this.file = file;
        this.time = time;
        this.entry = entry;
        this.instance = instance;
        this.state = state;
        this.progress = progress;
        this.ids = ids;
        this.differsFrom = differsFrom;
    }

    /**
     * Reads {@code csv} and replays {@code p} over it.
     *
     * @throws IllegalArgumentException with a message naming the file and line when the trace cannot be used
     * @throws IOException              when it cannot be read
     */
    static TraceScrubber load(Program p, Path csv) throws IOException {
        List<double[]> rows = new ArrayList<>();
        int[] columns;
        Engine probe = new Engine(p, RunOptions.defaults());
        int[] ids = probe.moduleIds();
        try (BufferedReader in = Files.newBufferedReader(csv, StandardCharsets.UTF_8)) {
            String header = in.readLine();
            if (header == null || !header.startsWith("time,")) {
                throw new IllegalArgumentException(PanelMsg.DIAGRAM_NOT_A_TRACE.text(csv + ":1:1"));
            }
            String[] names = header.split(",", -1);
            columns = new int[ids.length];
            Arrays.fill(columns, -1);
            for (int c = 1; c < names.length; c++) {
                if (names[c].startsWith("m")) {
                    int id = Integer.parseInt(names[c].substring(1));
                    int m = Arrays.binarySearch(ids, id);
                    if (m < 0) {
                        throw new IllegalArgumentException(PanelMsg.DIAGRAM_TRACE_EXTRA_MODULE.text(csv + ":1:1", id));
                    }
                    columns[m] = c;
                }
            }
            for (int m = 0; m < ids.length; m++) {
                if (columns[m] < 0) {
                    throw new IllegalArgumentException(PanelMsg.DIAGRAM_TRACE_NO_COLUMN.text(csv + ":1:1", ids[m]));
                }
            }
            String line;
            int number = 1;
            while ((line = in.readLine()) != null) {
                number++;
                if (line.isBlank()) {
                    continue;
                }
                String[] cells = line.split(",", -1);
                double[] row = new double[ids.length + 1];
                try {
                    row[0] = Double.parseDouble(cells[0]);
                    for (int m = 0; m < ids.length; m++) {
                        row[m + 1] = Double.parseDouble(cells[columns[m]]);
                    }
                } catch (NumberFormatException | ArrayIndexOutOfBoundsException e) {
                    throw new IllegalArgumentException(PanelMsg.DIAGRAM_TRACE_BAD_ROW.text(csv + ":" + number + ":1"));
                }
                rows.add(row);
            }
        }
        if (rows.size() < 2) {
            throw new IllegalArgumentException(PanelMsg.DIAGRAM_TRACE_TOO_SHORT.text(csv + ":1:1"));
        }
        double dt = Math.round((rows.get(1)[0] - rows.get(0)[0]) * 1e6) / 1e6;
        if (!(dt > 0)) {
            throw new IllegalArgumentException(PanelMsg.DIAGRAM_TRACE_TIME.text(csv + ":3:1"));
        }
        return replay(csv, p, dt, rows, ids);
    }

    private static TraceScrubber replay(Path csv, Program p, double dt, List<double[]> rows, int[] ids) {
        int n = ids.length;
        int count = rows.size();
        double[] time = new double[count];
        int[] entry = new int[count];
        int[][] instance = new int[count][n];
        int[][] state = new int[count][n];
        double[][] progress = new double[count][n];
        Engine e = new Engine(p, new RunOptions(dt, 0, List.of()));
        double[] differs = {Double.NaN};
        int[] row = {0};
        e.addObserver((tick, t, commanded) -> {
            double[] r = rows.get(row[0]);
            for (int m = 0; m < n && Double.isNaN(differs[0]); m++) {
                // the trace has six decimals
                if (Math.abs(commanded[m] - r[m + 1]) > 1e-6 * Math.max(1, Math.abs(r[m + 1]))) {
                    differs[0] = r[0];
                }
            }
        });
        e.start();
        boolean going = true;
        for (int k = 0; k < count; k++) {
            row[0] = k;
            time[k] = rows.get(k)[0];
            if (going) {
                going = e.step();
                entry[k] = e.entryIndex();
                e.moduleStates(instance[k], state[k]);
                e.moduleProgress(progress[k]);
            } else {
                entry[k] = -1;
                Arrays.fill(instance[k], -1);
                Arrays.fill(state[k], -1);
                Arrays.fill(progress[k], -1);
            }
        }
        return new TraceScrubber(csv, time, entry, instance, state, progress, ids, differs[0]);
    }

    /** The trace file. */
    Path file() {
        return file;
    }

    /** The number of ticks in the trace. */
    int ticks() {
        return time.length;
    }

    /** The trace's time at tick {@code k}, seconds. */
    double time(int k) {
        return time[k];
    }

    /** The first time at which the script's angles differ from the trace's, or NaN when they never do. */
    double differsFrom() {
        return differsFrom;
    }

    /** The states at tick {@code k}, as the live overlay takes them. */
    LiveStates.Frame frame(int k) {
        return new LiveStates.Frame(k, k, entry[k], ids, instance[k].clone(), state[k].clone(), progress[k].clone());
    }
}
