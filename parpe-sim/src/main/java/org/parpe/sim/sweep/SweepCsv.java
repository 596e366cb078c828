package org.parpe.sim.sweep;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.parpe.core.io.CsvCells;
import org.parpe.core.lang.Numbers;

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
        public String span() {
            return to > from ? "runs " + from + ".." + (to - 1) : "no runs";
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
        if (!row.error().isEmpty()) {
            String error = CsvCells.safe(row.error().replaceAll("[\\r\\n]+", " "));
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
                    throw new SweepException("not a row of " + (columns + (scored ? 1 : 0)) + " columns: '" + line + "'");
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
                rows.add(new SweepRow(p, m[0], m[1], m[2], m[3], m[4], m[5], m[6], f[columns - 2].equals("1"), error,
                        score));
            } catch (NumberFormatException e) {
                throw new SweepException("a column that should be a number is not, in '" + line + "'");
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
        Merger m = new Merger();
        for (Map.Entry<String, List<String>> shard : shards.entrySet()) {
            m.add(shard.getKey(), shard.getValue().stream().filter(l -> !l.isBlank()).toList());
        }
        m.checkShards();
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
        /** The framed shards by number, and the split they come from (the first one read). */
        private final TreeMap<Integer, String> shardFrom = new TreeMap<>();
        private Shard split;
        private final List<String> problems = new ArrayList<>();
        private final List<Integer> rerun = new ArrayList<>();

        void add(String name, List<String> lines) throws SweepException {
            Shard shard = lines.isEmpty() ? null : shardOf(lines.get(0));
            List<String> body = lines;
            if (shard != null) {
                sameSplit(name, shard);
                if (!lines.get(lines.size() - 1).equals(shardEnd(shard.k(), shard.n()))) {
                    problems.add(name + ": error: shard " + shard.k() + "/" + shard.n() + " is unfinished: it holds "
                            + Math.max(lines.size() - 2, 0) + " of its " + (shard.to() - shard.from()) + " runs ("
                            + shard.span() + "); its task was stopped or killed before the end");
                    rerun.add(shard.k());
                    shardFrom.put(shard.k(), name);
                    return;
                }
                body = lines.subList(1, lines.size() - 1);
            }
            int first = shard == null ? 1 : 2;
            if (body.isEmpty() || !body.get(0).startsWith("run,runs,")) {
                throw new SweepException(name + ":" + first + ": error: not a sweep result (its"
                        + " first line must be the header 'run,runs,...' that parpe sweep writes)");
            }
            if (header == null) {
                header = body.get(0);
                headerFrom = name;
            } else if (!header.equals(body.get(0))) {
                throw new SweepException(name + ":" + first + ": error: its columns differ from those of " + headerFrom
                        + "; only shards of one sweep can be merged");
            }
            for (int i = 1; i < body.size(); i++) {
                int run = row(name, i + first, body.get(i));
                if (shard != null && (run < shard.from() || run >= shard.to())) {
                    throw new SweepException(name + ":" + (i + first) + ": error: run " + run + " is not one of shard "
                            + shard.k() + "/" + shard.n() + " (" + shard.span() + ")");
                }
            }
            if (shard != null) {
                shardFrom.put(shard.k(), name);
            }
        }

        /** A shard of the same split as those before, and not one of them twice. */
        private void sameSplit(String name, Shard shard) throws SweepException {
            if (split == null) {
                split = shard;
            } else if (shard.n() != split.n() || shard.runs() != split.runs()) {
                throw new SweepException(name + ":1: error: shard " + shard.k() + "/" + shard.n() + " of a sweep of "
                        + shard.runs() + " runs, but " + shardFrom.firstEntry().getValue() + " is shard " + split.k()
                        + "/" + split.n() + " of a sweep of " + split.runs() + " runs; merge the files of one split"
                        + " only (a folder reused for another sweep or another number of shards?)");
            }
            String twice = shardFrom.get(shard.k());
            if (twice != null) {
                throw new SweepException(name + ":1: error: shard " + shard.k() + "/" + shard.n() + " is also "
                        + twice + "; give each shard once");
            }
        }

        /** Every shard of the split is here and finished, or an exception names those that are not. */
        void checkShards() throws IncompleteSweepException {
            if (split == null) {
                return;
            }
            for (int k = 1; k <= split.n(); k++) {
                if (!shardFrom.containsKey(k)) {
                    int[] r = SweepSpec.shard(split.runs(), k, split.n());
                    problems.add("error: shard " + k + "/" + split.n() + " is missing ("
                            + new Shard(k, split.n(), r[0], r[1], split.runs()).span() + ")");
                    rerun.add(k);
                }
            }
            if (!problems.isEmpty()) {
                java.util.Collections.sort(rerun);
                throw new IncompleteSweepException(String.join("\n", problems), rerun, split.n());
            }
        }

        /** Reads one row and returns its run number. */
        private int row(String name, int line, String text) throws SweepException {
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
            return run;
        }
    }

    private static void checkComplete(TreeMap<Integer, String> rows, int runs) throws SweepException {
        if (rows.size() == runs) {
            return;
        }
        if (runs < 0) {
            throw new SweepException("the files hold no runs, only the header; merge the files of a sweep's shards");
        }
        int missing = 0;
        while (rows.containsKey(missing)) {
            missing++;
        }
        throw new SweepException("runs are missing: " + (runs - rows.size()) + " of " + Math.max(runs, 0)
                + " (the first is run " + missing + "); is a shard missing or unfinished?");
    }
}
