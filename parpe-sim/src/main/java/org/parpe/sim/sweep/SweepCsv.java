package org.parpe.sim.sweep;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import org.parpe.core.model.Numbers;

/**
 * The CSV form of sweep rows: a header, then one line per run in combination order. Columns:
 * {@code run} (0-based), {@code runs} (the sweep's total, so that a merge can tell a missing
 * shard), {@code combination}, {@code repeat}, {@code seed}, one column per varied parameter,
 * then {@code duration_s}, {@code distance_m}, {@code forward_m}, {@code forward_speed_mps},
 * {@code speed_mps}, {@code max_tilt_deg}, {@code joint_travel_deg} (the energy proxy),
 * {@code fell} (0/1) and {@code error} (quoted; empty when the run went well). Measurements
 * are printed with {@code %.6f} in every locale, parameter values as the shortest exact decimal;
 * a run that could not start has empty measurements.
 */
public final class SweepCsv {
    private SweepCsv() {
    }

    /** The header line for a sweep of {@code axes}. */
    public static String header(List<Axis> axes) {
        StringBuilder b = new StringBuilder("run,runs,combination,repeat,seed");
        for (Axis a : axes) {
            b.append(',').append(a.name());
        }
        return b.append(",duration_s,distance_m,forward_m,forward_speed_mps,speed_mps,max_tilt_deg,joint_travel_deg,fell,error")
                .toString();
    }

    /** The header line for a sweep of {@code axes}; {@code scored}: with a last column {@code score} (a sweep in a world). */
    public static String header(List<Axis> axes, boolean scored) {
        return header(axes) + (scored ? ",score" : "");
    }

    /** The line of {@code row} in a sweep of {@code runs} runs; {@code scored}: with its score last. */
    public static String line(SweepRow row, int runs, boolean scored) {
        return line(row, runs) + (!scored ? "" : Double.isNaN(row.score()) ? "," : String.format(Locale.ROOT, ",%.6f", row.score()));
    }

    /** The line of {@code row} in a sweep of {@code runs} runs. */
    public static String line(SweepRow row, int runs) {
        Point p = row.point();
        StringBuilder b = new StringBuilder();
        b.append(p.index()).append(',').append(runs).append(',').append(p.combination()).append(',')
                .append(p.repeat()).append(',').append(p.seed());
        for (double v : p.values().values()) {
            b.append(',').append(Numbers.format(v));
        }
        for (double v : new double[] {row.duration(), row.distance(), row.forward(), row.forwardSpeed(), row.speed(),
            row.maxTiltDeg(), row.jointTravelDeg()}) {
            b.append(',').append(Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.6f", v));
        }
        b.append(',').append(row.fell() ? 1 : 0).append(',');
        if (!row.error().isEmpty()) {
            b.append('"').append(row.error().replaceAll("[\\r\\n]+", " ").replace("\"", "\"\"")).append('"');
        }
        return b.toString();
    }

    /**
     * Joins shard files (each as its lines, header first, with a name for messages) into the
     * lines of the one sweep: the same header, the runs ordered by number. Headers that differ,
     * a run found twice, or runs missing from {@code 0} to {@code runs - 1} throw with one line.
     */
    public static List<String> merge(Map<String, List<String>> shards) throws SweepException {
        Merger m = new Merger();
        for (Map.Entry<String, List<String>> shard : shards.entrySet()) {
            m.add(shard.getKey(), shard.getValue().stream().filter(l -> !l.isBlank()).toList());
        }
        checkComplete(m.rows, m.runs);
        List<String> out = new ArrayList<>();
        out.add(m.header);
        out.addAll(m.rows.values());
        return out;
    }

    /** The shards read so far: their header, the sweep's size, and the rows by run number. */
    private static final class Merger {
        private String header;
        private String headerFrom;
        private int runs = -1;
        private final TreeMap<Integer, String> rows = new TreeMap<>();
        private final Map<Integer, String> rowFrom = new TreeMap<>();

        void add(String name, List<String> lines) throws SweepException {
            if (lines.isEmpty() || !lines.get(0).startsWith("run,runs,")) {
                throw new SweepException(name + ":1: error: not a sweep result (its first line must be the header"
                        + " 'run,runs,...' that parpe sweep writes)");
            }
            if (header == null) {
                header = lines.get(0);
                headerFrom = name;
            } else if (!header.equals(lines.get(0))) {
                throw new SweepException(name + ":1: error: its columns differ from those of " + headerFrom
                        + "; only shards of one sweep can be merged");
            }
            for (int i = 1; i < lines.size(); i++) {
                row(name, i + 1, lines.get(i));
            }
        }

        private void row(String name, int line, String text) throws SweepException {
            String[] f = text.split(",", 3);
            String at = name + ":" + line + ": error: ";
            if (f.length < 3 || !f[0].matches("\\d{1,9}") || !f[1].matches("\\d{1,9}")) {
                throw new SweepException(at + "expected a run number and the number of runs, got '" + text + "'");
            }
            int run = Integer.parseInt(f[0]);
            int total = Integer.parseInt(f[1]);
            if (runs >= 0 && total != runs) {
                throw new SweepException(at + "a sweep of " + total + " runs, but the shards before are from a sweep of "
                        + runs);
            }
            runs = total;
            if (run >= total) {
                throw new SweepException(at + "run " + run + " in a sweep of " + total + " runs (numbered from 0)");
            }
            String before = rows.put(run, text);
            if (before != null) {
                throw new SweepException(at + "run " + run + " is also in " + rowFrom.get(run)
                        + "; were shards given twice or run with different --shard N?");
            }
            rowFrom.put(run, name);
        }
    }

    private static void checkComplete(TreeMap<Integer, String> rows, int runs) throws SweepException {
        if (rows.size() == runs) {
            return;
        }
        int missing = 0;
        while (rows.containsKey(missing)) {
            missing++;
        }
        throw new SweepException("runs are missing: " + (runs - rows.size()) + " of " + Math.max(runs, 0)
                + " (the first is run " + missing + "); is a shard missing or unfinished?");
    }
}
