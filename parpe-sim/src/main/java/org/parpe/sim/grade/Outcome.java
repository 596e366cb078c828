package org.parpe.sim.grade;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.parpe.sim.SimMetrics;

/**
 * What one student's run gave: ranked with its score and metrics, or failed with a reason (the
 * located errors of a script that does not load, a run-time error, or the limit it broke).
 * Crosses from {@link GradeChild} to the grading JVM as {@code key=value} lines.
 *
 * @param ranked    whether the run finished and counts
 * @param reason    why not (may span lines), or ""
 * @param score     the world's score
 * @param parts     the parts of the score in words
 * @param dx        how far the centre of mass went forwards (+x), m
 * @param distance  the length of the centre of mass's path, m
 * @param fell      whether the robot fell over
 * @param time      simulated seconds the run lasted
 */
public record Outcome(boolean ranked, String reason, double score, String parts, double dx, double distance, boolean fell,
               double time) {

    /** A run that does not count, and why (it did not start, or broke a limit). */
    public static Outcome failed(String reason) {
        return new Outcome(false, reason, 0, "", 0, 0, false, 0);
    }

    /** A run that started and ended with a run-time error at {@code time} simulated seconds, {@code reason} saying which. */
    static Outcome failedAt(String reason, double time) {
        return new Outcome(false, reason, 0, "", 0, 0, false, time);
    }

    static Outcome ran(SimMetrics m, double time) {
        return new Outcome(true, "", m.score().score(), m.score().inWords(), m.dx(), m.distance(), m.fell(), time);
    }

    /** The outcome as {@code key=value} lines, numbers with 6 decimals (newlines in values escaped). */
    String format() {
        StringBuilder b = new StringBuilder();
        b.append("ranked=").append(ranked).append('\n');
        b.append("reason=").append(escape(reason)).append('\n');
        b.append(String.format(Locale.ROOT, "score=%.6f%ndx=%.6f%ndistance=%.6f%ntime=%.6f%n", score, dx, distance, time));
        b.append("parts=").append(parts).append('\n');
        b.append("fell=").append(fell).append('\n');
        return b.toString();
    }

    /** Reads {@link #format}'s lines; null if they are not complete (the child died before printing them). */
    static Outcome parse(String text) {
        Map<String, String> v = new LinkedHashMap<>();
        for (String line : text.split("\n")) {
            int eq = line.indexOf('=');
            if (eq > 0) {
                v.put(line.substring(0, eq), line.substring(eq + 1));
            }
        }
        if (!v.keySet().containsAll(java.util.List.of("ranked", "reason", "score", "dx", "distance", "time", "parts", "fell"))) {
            return null;
        }
        try {
            return new Outcome(Boolean.parseBoolean(v.get("ranked")), unescape(v.get("reason")),
                    Double.parseDouble(v.get("score")), v.get("parts"), Double.parseDouble(v.get("dx")),
                    Double.parseDouble(v.get("distance")), Boolean.parseBoolean(v.get("fell")),
                    Double.parseDouble(v.get("time")));
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /** {@code s} on one line: backslashes, newlines and carriage returns escaped ({@link #unescape} reads it). */
    static String escape(String s) {
        return s.replace("\\", "\\\\").replace("\n", "\\n").replace("\r", "\\r");
    }

    static String unescape(String s) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '\\' && i + 1 < s.length()) {
                char n = s.charAt(++i);
                b.append(n == 'n' ? '\n' : n == 'r' ? '\r' : n);
            } else {
                b.append(c);
            }
        }
        return b.toString();
    }
}
