package org.parpe.sim.grade;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.parpe.core.xml.InputFiles;
import org.parpe.sim.text.SimMsg;

/**
 * The file of one shard of a grading ({@code parpe grade --shard K/N}): the outcomes of the
 * students FROM..TO−1 (their places in name order, the same split as a sweep's shards), each
 * with its trace's name, so that {@code parpe grade --merge} ranks the whole class into the
 * report a one-machine grading writes, byte for byte. Written whole at the shard's end: a
 * shard under its name is always complete. Text, UTF-8:
 * <pre>
 * parpe grade shard K/N: students FROM..TO of TOTAL
 * #INDEX NAME            (the student's place from 0, its name escaped as the outcome's reason)
 * trace=traces/NNN.csv   (or empty)
 * ranked=... reason=... score=... (the outcome, {@link Outcome#format})
 * </pre>
 */
public final class GradeShard {
    private static final Pattern HEAD = Pattern.compile("parpe grade shard (\\d{1,6})/(\\d{1,6}): students (\\d+)\\.\\.(\\d+) of (\\d+)");

    /**
     * What one shard's file holds.
     *
     * @param k        the shard's number, from 1
     * @param n        the number of shards
     * @param from     the first student's place (from 0)
     * @param to       one past the last student's place
     * @param total    the number of students of the class
     * @param names    the students' names, FROM..TO−1
     * @param outcomes their outcomes
     * @param traces   their traces (relative to the report folder, "" without one)
     */
    public record Part(int k, int n, int from, int to, int total, List<String> names, List<Outcome> outcomes,
                       List<String> traces) {
    }

    private GradeShard() {
    }

    /** The file name of shard {@code k} of {@code n} in the report folder. */
    public static String fileName(int k, int n) {
        return "shard-" + k + "-of-" + n + ".grade";
    }

    /** The text of shard {@code k}/{@code n}: {@code rows} are the students FROM..TO−1, in order. */
    public static String format(int k, int n, int from, int total, List<Row> rows) {
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "parpe grade shard %d/%d: students %d..%d of %d%n",
                k, n, from, from + rows.size(), total));
        for (int i = 0; i < rows.size(); i++) {
            Row r = rows.get(i);
            b.append('#').append(from + i).append(' ').append(Outcome.escape(r.student().name())).append('\n');
            b.append("trace=").append(r.trace()).append('\n');
            b.append(r.outcome().format());
        }
        return b.toString();
    }

    /** Reads a shard's file; the message of the exception names the file and line of what is wrong. */
    public static Part read(Path file) throws IOException {
        InputFiles.checkKind(file);
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        Matcher m = lines.isEmpty() ? null : HEAD.matcher(lines.get(0));
        if (m == null || !m.matches()) {
            throw new IOException(file + ":1: " + SimMsg.GRADE_SHARD_FIRST_LINE.text());
        }
        int[] v = new int[5];
        for (int i = 0; i < 5; i++) {
            v[i] = Integer.parseInt(m.group(i + 1));
        }
        List<String> names = new ArrayList<>();
        List<Outcome> outcomes = new ArrayList<>();
        List<String> traces = new ArrayList<>();
        int line = 1;
        while (line < lines.size()) {
            String head = lines.get(line);
            String expected = "#" + (v[2] + names.size()) + " ";
            if (!head.startsWith(expected)) {
                throw new IOException(file + ":" + (line + 1) + ": " + SimMsg.GRADE_SHARD_EXPECTED.text(expected.trim()));
            }
            int end = line + 1;
            while (end < lines.size() && !lines.get(end).startsWith("#")) {
                end++;
            }
            Outcome o = Outcome.parse(String.join("\n", lines.subList(line + 1, end)));
            String trace = lines.subList(line + 1, end).stream().filter(l -> l.startsWith("trace=")).findFirst()
                    .map(l -> l.substring(6)).orElse(null);
            if (o == null || trace == null) {
                throw new IOException(file + ":" + (line + 1) + ": " + SimMsg.GRADE_SHARD_INCOMPLETE.text(expected.trim()));
            }
            names.add(Outcome.unescape(head.substring(expected.length())));
            outcomes.add(o);
            traces.add(trace);
            line = end;
        }
        if (names.size() != v[3] - v[2]) {
            throw new IOException(file + ": " + SimMsg.GRADE_SHARD_HOLDS.text(names.size(), v[3] - v[2]));
        }
        return new Part(v[0], v[1], v[2], v[3], v[4], List.copyOf(names), List.copyOf(outcomes), List.copyOf(traces));
    }
}
