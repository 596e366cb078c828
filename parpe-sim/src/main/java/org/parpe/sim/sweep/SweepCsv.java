package org.parpe.sim.sweep;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.parpe.core.text.Message;
import org.parpe.core.io.CsvCells;
import org.parpe.core.lang.Numbers;
import org.parpe.sim.text.SimMsg;

/**
 * The CSV form of sweep rows: a header, then one line per run in combination order. Columns:
 * {@code run} (0-based), {@code runs} (the sweep's total, so that a merge can tell a missing
 * shard), {@code combination}, {@code repeat}, {@code seed}, one column per varied parameter,
 * then {@code duration_s}, {@code distance_m}, {@code forward_m}, {@code forward_speed_mps},
 * {@code speed_mps}, {@code max_tilt_deg}, {@code joint_travel_deg} (the energy proxy),
 * {@code fell} (0/1) and {@code error} (quoted, made safe for spreadsheets by {@link CsvCells#safe}; empty when the
 * run went well). Measurements
 * are printed with {@code %.6f} in every locale, parameter values as the shortest exact decimal;
 * a run that could not start has empty measurements.
 *
 * <p>A shard's file ({@code parpe sweep --shard K/N}) is framed by two comment lines, so that a
 * shard cut short (a cancelled, timed-out or killed cluster task) cannot pass for a whole one:
 * {@link #shardStart} before the header records which runs it must hold, {@link #shardEnd} after
 * the last row says that it holds them all. {@link #merge} checks both and drops them.
 */
public final class SweepCsv {
    /** The last column of a sweep in a world. */
    private static final String SCORE = "score";
    private static final Pattern SHARD_START =
            Pattern.compile("# parpe sweep shard (\\d{1,6})/(\\d{1,6}): (\\d{1,9}) runs from run (\\d{1,9}) of (\\d{1,9})");
    private static final String SHARD_END = "# parpe sweep shard %d/%d: complete";

    private SweepCsv() {
    }

    /** The first line of shard {@code k} of {@code n}, which holds runs {@code [from, to)} of {@code runs}. */
    public static String shardStart(int k, int n, int from, int to, int runs) {
        return "# parpe sweep shard " + k + "/" + n + ": " + (to - from) + " runs from run " + from + " of " + runs;
    }

    /** The last line of shard {@code k} of {@code n}, written once its last row is. */
    public static String shardEnd(int k, int n) {
        return String.format(Locale.ROOT, SHARD_END, k, n);
    }

    /**
     * The shard a file's first line announces ({@link #shardStart}), or {@code null} when it is
     * not a shard's first line.
     */
    public static Shard shardOf(String firstLine) {
        Matcher m = SHARD_START.matcher(firstLine);
        if (!m.matches()) {
            return null;
        }
        int from = Integer.parseInt(m.group(4));
        return new Shard(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)), from,
                from + Integer.parseInt(m.group(3)), Integer.parseInt(m.group(5)));
    }

    /**
     * A shard as its first line describes it: the {@code k}-th of {@code n}, holding runs
     * {@code [from, to)} of a sweep of {@code runs}.
     *
     * @param k    which shard, from 1
     * @param n    into how many shards the sweep was split
     * @param from its first run
     * @param to   one past its last run
     * @param runs the whole sweep's number of runs
     */
    public record Shard(int k, int n, int from, int to, int runs) {
        /** Its runs as people count them ({@code "runs 4950..6599"}). */
        public Message span() {
            return to > from ? Message.of(SimMsg.SHARD_SPAN, from, to - 1) : Message.of(SimMsg.SHARD_NO_RUNS);
        }
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
        return header(axes) + (scored ? "," + SCORE : "");
    }

    /** Whether {@code header} is that of a sweep in a world: its last column is the score. */
    public static boolean scored(String header) {
        return header.endsWith("," + SCORE);
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
        if (!row.ok()) {
            // English in every language: the file is data for scripts, and shards from machines
            // in different languages merge into one (docs/decisions.md, "Language of messages")
            String error = CsvCells.safe(row.error().format(Locale.ROOT).replaceAll("[\\r\\n]+", " "));
            b.append('"').append(error.replace("\"", "\"\"")).append('"');
        }
        return b.toString();
    }

    /**
     * The rows of a sweep's CSV lines, header first (as {@link #merge} returns them): the
     * inverse of {@link #header} and {@link #line}, for drawing a merged sweep.
     */
    public static SweepResult read(List<String> lines) throws SweepException {
        String[] head = lines.get(0).split(",", -1);
        boolean scored = scored(lines.get(0));
        int params = head.length - 14 - (scored ? 1 : 0);
        int columns = params + 14;
        List<SweepRow> rows = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            String text = line;
            double score = Double.NaN;
            try {
                if (scored) { // the score follows the quoted error, which may hold commas
                    int last = text.lastIndexOf(',');
                    String s = last < 0 ? "" : text.substring(last + 1);
                    score = s.isEmpty() ? Double.NaN : Double.parseDouble(s);
                    text = last < 0 ? text : text.substring(0, last);
                }
                String[] f = text.split(",", columns);
                if (params < 0 || f.length != columns) {
                    throw new SweepException(SimMsg.CSV_COLUMNS, columns + (scored ? 1 : 0), line);
                }
                Map<String, Double> values = new java.util.LinkedHashMap<>();
                for (int a = 0; a < params; a++) {
                    values.put(head[5 + a], Double.valueOf(f[5 + a]));
                }
                double[] m = new double[7];
                for (int j = 0; j < 7; j++) {
                    String v = f[5 + params + j];
                    m[j] = v.isEmpty() ? Double.NaN : Double.parseDouble(v);
                }
                String error = f[columns - 1];
                if (error.length() >= 2 && error.startsWith("\"") && error.endsWith("\"")) {
                    error = error.substring(1, error.length() - 1).replace("\"\"", "\"");
                }
                Point p = new Point(Integer.parseInt(f[0]), Integer.parseInt(f[2]), Integer.parseInt(f[3]), values,
                        Long.parseLong(f[4]));
                rows.add(new SweepRow(p, m[0], m[1], m[2], m[3], m[4], m[5], m[6], f[columns - 2].equals("1"),
                        error.isEmpty() ? Message.EMPTY : Message.verbatim(error),
                        score));
            } catch (NumberFormatException e) {
                throw new SweepException(SimMsg.CSV_NOT_A_NUMBER, line);
            }
        }
        return new SweepResult(rows, false);
    }

    /**
     * Joins shard files (each as its lines, with a name for messages) into the lines of the one
     * sweep: the same header, the runs ordered by number, without the shards' framing lines.
     * Headers that differ, a run found twice, shards of different splits, or runs missing from
     * {@code 0} to {@code runs - 1} throw; unfinished and missing shards throw an
     * {@link IncompleteSweepException} that names each of them.
     */
    public static List<String> merge(Map<String, List<String>> shards) throws SweepException {
        Map<String, Source> sources = new java.util.LinkedHashMap<>();
        shards.forEach((name, lines) -> sources.put(name, lines::stream));
        List<String> out = new ArrayList<>();
        try {
            merge(sources, out::add);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e); // lines in memory are never read from a file
        }
        return out;
    }

    /**
     * Joins shard files as {@link #merge(Map)} does, handing each line of the merged sweep to
     * {@code out} in order and returning the number of runs. When every file is a framed shard
     * ({@link #shardStart}), the files are read twice as streams, first their framing and headers,
     * then their rows, which must be in run order as {@code sweep} writes them: a cluster sweep
     * of millions of runs merges in little memory. Other files (unframed sweep results) are held
     * in memory and may be in any order.
     */
    public static int merge(Map<String, Source> files, Sink out) throws SweepException, java.io.IOException {
        boolean framed = true;
        for (Source f : files.values()) {
            try (java.util.stream.Stream<String> lines = f.lines()) {
                framed &= lines.filter(l -> !l.isBlank()).findFirst().map(SweepCsv::shardOf).isPresent();
            }
        }
        Merger m = new Merger();
        for (Map.Entry<String, Source> f : files.entrySet()) {
            if (framed) {
                m.scan(f.getKey(), f.getValue());
            } else {
                try (java.util.stream.Stream<String> lines = f.getValue().lines()) {
                    m.add(f.getKey(), lines.filter(l -> !l.isBlank()).toList());
                }
            }
        }
        m.checkShards();
        if (framed) {
            return m.stream(files, out);
        }
        checkComplete(m.rows, m.runs);
        out.line(m.header);
        for (String row : m.rows.values()) {
            out.line(row);
        }
        return m.rows.size();
    }

    /** The lines of a file to merge, which may be read more than once; the caller closes the stream. */
    @FunctionalInterface
    public interface Source {
        java.util.stream.Stream<String> lines() throws java.io.IOException;
    }

    /** Where the merged lines go, one at a time. */
    @FunctionalInterface
    public interface Sink {
        void line(String line) throws java.io.IOException, SweepException;
    }

    static void checkComplete(TreeMap<Integer, String> rows, int runs) throws SweepException {
        if (rows.size() == runs) {
            return;
        }
        if (runs < 0) {
            throw new SweepException(SimMsg.MERGE_ONLY_HEADER);
        }
        int missing = 0;
        while (rows.containsKey(missing)) {
            missing++;
        }
        throw new SweepException(SimMsg.MERGE_RUNS_MISSING, runs - rows.size(), Math.max(runs, 0), missing);
    }
}
