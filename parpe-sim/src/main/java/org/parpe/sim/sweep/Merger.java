package org.parpe.sim.sweep;

import static org.parpe.sim.sweep.SweepCsv.shardEnd;
import static org.parpe.sim.sweep.SweepCsv.shardOf;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.parpe.core.diag.Severity;
import org.parpe.core.text.Message;
import org.parpe.sim.sweep.SweepCsv.Shard;
import org.parpe.sim.text.SimMsg;

/**
 * The shards read so far by {@link SweepCsv#merge}: their header, the sweep's size, and the rows
 * by run number, or, for framed shards read as streams, only what their framing and header say.
 */
final class Merger {
    String header;
    private String headerFrom;
    int runs = -1;
    final TreeMap<Integer, String> rows = new TreeMap<>();
    private final Map<Integer, String> rowFrom = new TreeMap<>();
    /** The framed shards by number, and the split they come from (the first one read). */
    private final TreeMap<Integer, String> shardFrom = new TreeMap<>();
    private Shard split;
    /** The framed shards by number, as their first lines describe them. */
    private final Map<Integer, Shard> shards = new TreeMap<>();
    private final List<Message> problems = new ArrayList<>();
    private final List<Integer> rerun = new ArrayList<>();

    void add(String name, List<String> lines) throws SweepException {
        Shard shard = lines.isEmpty() ? null : shardOf(lines.get(0));
        List<String> body = lines;
        if (shard != null) {
            sameSplit(name, shard);
            if (!lines.get(lines.size() - 1).equals(shardEnd(shard.k(), shard.n()))) {
                unfinished(name, shard, lines.size());
                return;
            }
            body = lines.subList(1, lines.size() - 1);
        }
        int first = shard == null ? 1 : 2;
        header(name, first, body.isEmpty() ? null : body.get(0));
        for (int i = 1; i < body.size(); i++) {
            int run = row(name, i + first, body.get(i));
            if (shard != null && (run < shard.from() || run >= shard.to())) {
                throw at(name + ":" + (i + first), SimMsg.MERGE_RUN_NOT_IN_SHARD, run, kn(shard), shard.span());
            }
        }
        if (shard != null) {
            shardFrom.put(shard.k(), name);
        }
    }

    /** The header of file {@code name} at line {@code at}: a sweep's, and that of the files before. */
    private void header(String name, int at, String line) throws SweepException {
        if (line == null || !line.startsWith("run,runs,")) {
            throw at(name + ":" + at, SimMsg.MERGE_NOT_A_RESULT);
        }
        if (header == null) {
            header = line;
            headerFrom = name;
        } else if (!header.equals(line)) {
            throw at(name + ":" + at, SimMsg.MERGE_COLUMNS_DIFFER, headerFrom);
        }
    }

    /**
     * The first pass over framed shard {@code name}, read as a stream: its framing, its header
     * and whether it is finished, as {@link #add} checks them, without keeping its rows.
     */
    void scan(String name, SweepCsv.Source source) throws SweepException, IOException {
        String first = null;
        String second = null;
        String last = null;
        int count = 0;
        try (Stream<String> lines = source.lines()) {
            for (Iterator<String> it = lines.filter(l -> !l.isBlank()).iterator(); it.hasNext(); count++) {
                last = it.next();
                first = first == null ? last : first;
                second = count == 1 ? last : second;
            }
        }
        Shard shard = shardOf(first);
        sameSplit(name, shard);
        shards.put(shard.k(), shard);
        if (count < 2 || !last.equals(shardEnd(shard.k(), shard.n()))) {
            unfinished(name, shard, count);
            return;
        }
        header(name, 2, count > 2 ? second : null);
        shardFrom.put(shard.k(), name);
    }

    /**
     * The second pass over framed shards, in shard order: each one's rows, which must be its runs
     * in order, go to {@code out} after the header; returns the number of runs.
     */
    int stream(Map<String, SweepCsv.Source> files, SweepCsv.Sink out) throws SweepException, IOException {
        out.line(header);
        for (Map.Entry<Integer, String> e : shardFrom.entrySet()) {
            String name = e.getValue();
            Shard shard = shards.get(e.getKey());
            int run = shard.from();
            int line = 2;
            runs = shard.runs();
            try (Stream<String> lines = files.get(name).lines()) {
                Iterator<String> it = lines.filter(l -> !l.isBlank()).iterator();
                for (int i = 0; i < 2 && it.hasNext(); i++) {
                    it.next(); // the framing line, the header
                }
                if (!it.hasNext()) { // the first pass found at least the end line after them
                    throw at(name, SimMsg.MERGE_CHANGED);
                }
                for (String text = it.next(); it.hasNext(); text = it.next()) {
                    line++;
                    int found = runOf(name, line, text);
                    if (found < shard.from() || found >= shard.to()) {
                        throw at(name + ":" + line, SimMsg.MERGE_RUN_NOT_IN_SHARD, found, kn(shard), shard.span());
                    }
                    if (found != run) {
                        throw at(name + ":" + line, SimMsg.MERGE_RUN_OUT_OF_ORDER, found, run);
                    }
                    out.line(text);
                    run++;
                }
            }
            if (run != shard.to()) {
                throw at(name, SimMsg.MERGE_SHORT_COMPLETE, kn(shard), run - shard.from(), shard.to() - shard.from(),
                        shard.span());
            }
        }
        return split == null ? 0 : split.runs();
    }

    private void unfinished(String name, Shard shard, int lines) {
        problems.add(located(name, SimMsg.MERGE_UNFINISHED, kn(shard), Math.max(lines - 2, 0), shard.to() - shard.from(),
                shard.span()));
        rerun.add(shard.k());
        shardFrom.put(shard.k(), name);
    }

    /** A shard of the same split as those before, and not one of them twice. */
    private void sameSplit(String name, Shard shard) throws SweepException {
        if (split == null) {
            split = shard;
        } else if (shard.n() != split.n() || shard.runs() != split.runs()) {
            throw at(name + ":1", SimMsg.MERGE_OTHER_SPLIT, kn(shard), shard.runs(), shardFrom.firstEntry().getValue(),
                    kn(split), split.runs());
        }
        String twice = shardFrom.get(shard.k());
        if (twice != null) {
            throw at(name + ":1", SimMsg.MERGE_SHARD_TWICE, kn(shard), twice);
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
                problems.add(Message.of(SimMsg.UNPLACED, Severity.ERROR.word(), Message.of(SimMsg.MERGE_SHARD_MISSING,
                        k + "/" + split.n(), new Shard(k, split.n(), r[0], r[1], split.runs()).span())));
                rerun.add(k);
            }
        }
        if (!problems.isEmpty()) {
            java.util.Collections.sort(rerun);
            throw new IncompleteSweepException(problems, rerun, split.n());
        }
    }

    /** Reads one row and returns its run number. */
    private int row(String name, int line, String text) throws SweepException {
        int run = runOf(name, line, text);
        String before = rows.put(run, text);
        if (before != null) {
            throw at(name + ":" + line, SimMsg.MERGE_RUN_TWICE, run, rowFrom.get(run));
        }
        rowFrom.put(run, name);
        return run;
    }

    /** The run number of a row, checked against the sweep's number of runs (the first row's). */
    private int runOf(String name, int line, String text) throws SweepException {
        String[] f = text.split(",", 3);
        String where = name + ":" + line;
        if (f.length < 3 || !f[0].matches("\\d{1,9}") || !f[1].matches("\\d{1,9}")) {
            throw at(where, SimMsg.MERGE_NOT_A_ROW, text);
        }
        int run = Integer.parseInt(f[0]);
        int total = Integer.parseInt(f[1]);
        if (runs >= 0 && total != runs) {
            throw at(where, SimMsg.MERGE_OTHER_SIZE, total, runs);
        }
        runs = total;
        if (run >= total) {
            throw at(where, SimMsg.MERGE_RUN_TOO_LARGE, run, total);
        }
        return run;
    }

    /** Problem {@code key} of the file at {@code where} ({@code FILE:LINE} or {@code FILE}): {@code WHERE: error: MESSAGE}. */
    private static Message located(String where, SimMsg key, Object... args) {
        return Message.of(SimMsg.LOAD_ERROR, where, Severity.ERROR.word(), Message.of(key, args));
    }

    private static SweepException at(String where, SimMsg key, Object... args) {
        return new SweepException(located(where, key, args));
    }

    /** A shard as its number and the split's, {@code K/N}. */
    private static String kn(Shard s) {
        return s.k() + "/" + s.n();
    }
}
