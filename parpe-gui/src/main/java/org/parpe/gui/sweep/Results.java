package org.parpe.gui.sweep;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.lang.Numbers;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.sweep.Constraints;
import java.util.function.Predicate;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.SweepResult;
import org.parpe.sim.sweep.SweepRow;

/**
 * The rows of one sweep or optimisation as the dialog shows them, in the engine's order
 * (combination order for a sweep, evaluation order for an optimisation). Memory stays bounded
 * whatever the number of runs (a million random runs took the IDE to 3.4 GB, issue 23 item 13):
 * the table and the plot get the first {@link #KEEP} rows; the best row and the counts are kept
 * as rows come; every row also goes, as its CSV line, to a temporary file once there are more
 * than {@link #KEEP}, from which Save CSV… writes them all. UI thread only.
 */
final class Results {
    /** How many rows the table and the plot show at most. */
    static final int KEEP = 20_000;

    /** Whether rows come from a sweep or from an optimisation. */
    enum Mode { SWEEP, OPTIMISE }

    private final Path script;
    private final Mode mode;
    private final List<String> parameters;
    private final Objective objective;
    private final Constraints constraints;
    private final Map<String, Double> own;
    private final int keep;
    private final int runs;
    private final boolean scored;
    private final List<SweepRow> rows = new ArrayList<>();
    private SweepRow best;
    private int count;
    private int failed;
    private int fell;
    private Path spill;
    private java.io.BufferedWriter spillOut;
    /** Why the rows beyond {@link #KEEP} could not be kept for Save CSV… (a full disk), or null. */
    private String spillError;

    /**
     * {@code own}: the script's own values of {@code parameters} (its {@code value}s), to tell a best
     * run that is only them; {@code keep}: the rows kept for the table and the plot ({@link #KEEP});
     * {@code runs}: how many runs there are to be (the CSV's {@code runs} column).
     */
    Results(Path script, Mode mode, List<String> parameters, Map<String, Double> own, Objective objective, Constraints constraints,
            int keep, int runs) {
        this(script, mode, parameters, own, objective, constraints, keep, runs, false);
    }

    /** As above; {@code scored}: the runs are in a world, so each has a score (a column of the table and the CSV). */
    Results(Path script, Mode mode, List<String> parameters, Map<String, Double> own, Objective objective, Constraints constraints,
            int keep, int runs, boolean scored) {
        this.scored = scored;
        this.keep = keep;
        this.runs = runs;
        this.script = script;
        this.mode = mode;
        this.parameters = List.copyOf(parameters);
        this.own = Map.copyOf(own);
        this.objective = objective;
        this.constraints = constraints;
    }

    /** The path of the script the runs were made with. */
    Path script() {
        return script;
    }

    Mode mode() {
        return mode;
    }

    /** Whether the runs are in a world: each has a score. */
    boolean scored() {
        return scored;
    }

    /** The varied (or searched) parameters, in the order of the table's columns. */
    List<String> parameters() {
        return parameters;
    }

    Objective objective() {
        return objective;
    }

    Constraints constraints() {
        return constraints;
    }

    /** The rows the table and the plot show: the first {@link #KEEP} (all of them unless there are more). */
    List<SweepRow> rows() {
        return java.util.Collections.unmodifiableList(rows);
    }

    /** How many rows came, kept or not. */
    int count() {
        return count;
    }

    /** How many rows came with an error. */
    int failed() {
        return failed;
    }

    /** How many rows came without an error but with a robot that fell over. */
    int fell() {
        return fell;
    }

    /** Whether every row is in {@link #rows} (else Save CSV… writes them from the temporary file). */
    boolean complete() {
        return count == rows.size();
    }

    void add(SweepRow row) {
        count++;
        if (!row.ok()) {
            failed++;
        } else if (row.fell()) {
            fell++;
        }
        if (acceptable(row) && (best == null || objective.of(row) > objective.of(best))) {
            best = row; // the first among equals, as SweepResult.best
        }
        if (rows.size() < keep) {
            rows.add(row);
            return;
        }
        if (spillError != null) {
            return;
        }
        try {
            if (spillOut == null) {
                spill = java.nio.file.Files.createTempFile("parpe-sweep-", ".csv");
                spill.toFile().deleteOnExit();
                spillOut = java.nio.file.Files.newBufferedWriter(spill);
                for (SweepRow r : rows) {
                    spillOut.write(org.parpe.sim.sweep.SweepCsv.line(r, runs, scored));
                    spillOut.write('\n');
                }
            }
            spillOut.write(org.parpe.sim.sweep.SweepCsv.line(row, runs, scored));
            spillOut.write('\n');
        } catch (java.io.IOException e) {
            lost(e);
        }
    }

    /** The temporary file could not be written: the rows beyond {@link #KEEP} cannot be saved; Save CSV… will say why. */
    private void lost(java.io.IOException e) {
        spillError = ToolMsg.SWEEP_SPILL_ERROR.text(keep, e.getMessage());
        discard();
    }

    /** Why not every row can be saved (see {@link #spilled}), or null. */
    String spillError() {
        return spillError;
    }

    /** Replaces the rows with the engine's final list (the same runs, in its order; an optimisation's few). */
    void replace(List<SweepRow> all) {
        discard();
        spillError = null;
        rows.clear();
        best = null;
        count = 0;
        failed = 0;
        fell = 0;
        all.forEach(this::add);
    }

    /** The temporary file with the rows' CSV lines, or null (see {@link #spill}). */
    Path spillFile() {
        return spill;
    }

    /**
     * The rows' CSV lines in the temporary file as they stand now, opened for reading: null while
     * {@link #complete}, or when the file could not be written ({@link #spillError}). The reader
     * sees whole lines only, however many rows come after, and can still read them after
     * {@link #discard} (a new sweep began while Save CSV… writes). The caller closes it.
     */
    Spill spill() throws java.io.IOException {
        try {
            if (spillOut != null) {
                spillOut.flush();
            }
        } catch (java.io.IOException e) {
            lost(e);
        }
        if (spill == null) {
            return null;
        }
        java.nio.channels.FileChannel in = java.nio.channels.FileChannel.open(spill, java.nio.file.StandardOpenOption.READ);
        return new Spill(in, in.size());
    }

    /** The first {@code bytes} of an open temporary file: whole CSV lines. */
    record Spill(java.nio.channels.FileChannel in, long bytes) implements AutoCloseable {
        /** Copies the lines to {@code out}. */
        void copyTo(java.io.OutputStream out) throws java.io.IOException {
            java.nio.channels.WritableByteChannel to = java.nio.channels.Channels.newChannel(out);
            for (long at = 0; at < bytes;) {
                at += in.transferTo(at, bytes - at, to);
            }
        }

        @Override
        public void close() throws java.io.IOException {
            in.close();
        }
    }

    /** Deletes the temporary file, if any (the dialog closed, or another sweep began). */
    void discard() {
        try {
            if (spillOut != null) {
                spillOut.close();
            }
            if (spill != null) {
                java.nio.file.Files.deleteIfExists(spill);
            }
        } catch (java.io.IOException e) {
            // A temporary file left behind is deleted when the IDE exits (deleteOnExit).
        }
        spillOut = null;
        spill = null;
    }

    /**
     * The rule of "best": a sweep's is {@code parpe sweep}'s ({@link SweepResult#STANDING}: a run
     * whose robot fell over never counts); an optimisation's is its constraints.
     */
    private Predicate<SweepRow> rule() {
        return mode == Mode.SWEEP ? SweepResult.STANDING : r -> constraints.violation(r) == 0;
    }

    /** Whether {@code row} may be the best: it ran without error, has a measurement and meets {@link #rule}. */
    boolean acceptable(SweepRow row) {
        return SweepResult.contender(row, objective, rule());
    }

    /** The acceptable row with the highest objective, the earliest among equals, or null. */
    SweepRow best() {
        return best;
    }

    /**
     * The number of {@code row} in the engine's order, from 0 as {@code parpe sweep}'s {@code run}
     * column counts (-1 when it is not one of these rows).
     */
    int number(SweepRow row) {
        if (mode == Mode.SWEEP) {
            return row.point().index();
        }
        for (int i = 0; i < rows.size(); i++) {
            if (rows.get(i) == row) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Whether {@code row} ran with the script's own values of every varied parameter (an
     * optimisation starts there): then nothing the sweep tried beat the script as it is.
     */
    boolean scriptsOwn(SweepRow row) {
        if (parameters.isEmpty()) {
            return false;
        }
        for (String p : parameters) {
            Double v = row.values().get(p);
            Double o = own.get(p);
            if (v == null || o == null || Math.abs(v - o) > 1e-9 * Math.max(1, Math.abs(o))) {
                return false;
            }
        }
        return true;
    }

    /** The sentence that names the best row {@code best} after a finished or stopped sweep. */
    String bestSentence(SweepRow best) {
        String measured = (best.fell() ? ToolMsg.SWEEP_MEASURED_FELL : ToolMsg.SWEEP_MEASURED)
                .text(RunSettings.label(objective), ResultsTable.number(objective.of(best)));
        return (scriptsOwn(best) ? ToolMsg.SWEEP_NOTHING_BEAT : ToolMsg.SWEEP_BEST).text(number(best), describe(best.values()), measured);
    }

    /** The parameter values of the best row, or an empty map. */
    Map<String, Double> bestValues() {
        SweepRow b = best();
        return b == null ? Map.of() : new LinkedHashMap<>(b.values());
    }

    /** {@code values} as {@code name = value, ...}. */
    static String describe(Map<String, Double> values) {
        StringBuilder b = new StringBuilder();
        values.forEach((k, v) -> b.append(b.length() == 0 ? "" : ", ").append(k).append(" = ").append(Numbers.format(v)));
        return b.toString();
    }
}
