package org.parpe.cli.bench;

import org.parpe.cli.text.CliMsg;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * The figures of one run of {@code parpe bench}, in the order they were printed, each checked
 * against its {@link Goal}. The same {@code name=value} lines are what bench prints, what
 * {@code --save} writes and what {@code --compare} reads, so a saved standard output compares
 * as well as a saved file.
 */
final class BenchResults {
    private static final String NOTE = "  # ";
    private final Map<String, String> figures = new LinkedHashMap<>();
    private final List<Goal> goals;

    BenchResults(List<Goal> goals) {
        this.goals = goals;
    }

    /** Reads a file written by {@code --save} (or a saved standard output of bench). */
    static BenchResults read(Path file, List<Goal> goals) throws IOException {
        BenchResults r = new BenchResults(goals);
        for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
            r.take(line);
        }
        return r;
    }

    /** The figures as {@code name=value} lines, as {@code --save} writes them. */
    String text() {
        StringBuilder s = new StringBuilder();
        figures.forEach((name, value) -> s.append(name).append('=').append(value).append('\n'));
        return s.toString();
    }

    /**
     * Takes one line a benchmark printed and returns it as bench shows it: a figure with a goal
     * gets the goal and whether it holds beside it; other lines pass unchanged.
     */
    String take(String line) {
        int eq = line.indexOf('=');
        if (line.startsWith("#") || eq <= 0 || line.substring(0, eq).contains(" ")) {
            return line;
        }
        String name = line.substring(0, eq);
        int note = line.indexOf(NOTE, eq);
        String value = (note < 0 ? line.substring(eq + 1) : line.substring(eq + 1, note)).trim();
        figures.put(name, value);
        Goal g = goal(name);
        Double v = value(value);
        return name + "=" + value + (g == null || v == null ? "" : NOTE + g.verdict(v));
    }

    /** A stream whose lines go through {@link #take} to {@code target} as they are printed. */
    PrintStream printer(PrintWriter target) {
        return new PrintStream(new OutputStream() {
            private final ByteArrayOutputStream line = new ByteArrayOutputStream();

            @Override
            public void write(int b) {
                if (b == '\n') {
                    target.println(take(line.toString(StandardCharsets.UTF_8)));
                    target.flush();
                    line.reset();
                } else {
                    line.write(b);
                }
            }
        }, true, StandardCharsets.UTF_8);
    }

    /** The figures, by name. */
    Map<String, String> figures() {
        return figures;
    }

    /** The first goal for the figure called {@code name}, or null. */
    Goal goal(String name) {
        for (Goal g : goals) {
            if (g.appliesTo(name)) {
                return g;
            }
        }
        return null;
    }

    /** One line on the goals: how many hold, which figures missed theirs, which goals had no figure. */
    String summary() {
        int held = 0;
        List<String> missed = new ArrayList<>();
        Set<Goal> measured = new LinkedHashSet<>();
        for (Map.Entry<String, String> f : figures.entrySet()) {
            Goal g = goal(f.getKey());
            Double v = value(f.getValue());
            if (g != null && v != null) {
                measured.add(g);
                if (g.holds(v)) {
                    held++;
                } else {
                    missed.add(f.getKey());
                }
            }
        }
        List<String> unmeasured = goals.stream().filter(g -> !measured.contains(g)).map(Goal::figures).toList();
        // "# goals:" stays: bench leaves the line of each forked benchmark out by it
        String said = missed.isEmpty() ? CliMsg.GOALS.text(held, 0) : CliMsg.GOALS_MISSED.text(held, missed.size(),
                String.join(", ", missed));
        return "# goals: " + (unmeasured.isEmpty() ? said : CliMsg.NOT_MEASURED.text(said, String.join(", ", unmeasured)));
    }

    /**
     * Prints two runs side by side: per figure (those of {@code before} first) its two values,
     * the change in per cent and, for a figure with a goal, whether it held in each run.
     */
    static void compare(PrintWriter out, String beforeLabel, BenchResults before, String afterLabel, BenchResults after) {
        Set<String> names = new LinkedHashSet<>(before.figures.keySet());
        names.addAll(after.figures.keySet());
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {CliMsg.FIGURE.text(), beforeLabel, afterLabel, CliMsg.CHANGE.text(), CliMsg.GOAL.text()});
        for (String name : names) {
            String a = before.figures.getOrDefault(name, "-");
            String b = after.figures.getOrDefault(name, "-");
            Double va = value(a);
            Double vb = value(b);
            String change = va == null || vb == null || va == 0 || name.startsWith(Machine.PREFIX) ? "" : String.format(Locale.ROOT, "%+.1f%%", (vb / va - 1) * 100);
            Goal g = after.goal(name);
            String goal = g == null ? "" : g.describe() + ": " + verdict(g, va) + " -> " + verdict(g, vb);
            rows.add(new String[] {name, a, b, change, goal});
        }
        int[] width = new int[4];
        for (String[] r : rows) {
            for (int i = 0; i < width.length; i++) {
                width[i] = Math.max(width[i], r[i].length());
            }
        }
        for (String[] r : rows) {
            out.println(String.format(Locale.ROOT, "%-" + width[0] + "s  %" + width[1] + "s  %" + width[2] + "s  %"
                    + width[3] + "s  %s", (Object[]) r).stripTrailing());
        }
        String one = machine(before);
        String other = machine(after);
        if (one != null && other != null && !one.equals(other)) {
            out.println("# " + CliMsg.OTHER_MACHINE.text(one, other));
        }
    }

    /** The processor and the number of cores a run names, or null for a run that names none. */
    private static String machine(BenchResults run) {
        String cpu = run.figures.get(Machine.CPU);
        String cores = run.figures.get(Machine.CORES);
        return cpu == null || cores == null ? null : cpu + " × " + cores;
    }

    private static String verdict(Goal g, Double v) {
        return v == null ? "-" : (g.holds(v) ? CliMsg.HOLDS : CliMsg.MISSED).text();
    }

    /** The number a figure's value is, or null for a word ({@code true}, {@code skipped ...}). */
    static Double value(String text) {
        try {
            return Double.valueOf(text);
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /** A number as bench prints a bound: whole numbers without a fraction. */
    static String number(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? String.valueOf((long) v) : String.valueOf(v);
    }
}
