package org.parpe.serial.record;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.parpe.core.edit.ElementWriter;
import org.parpe.serial.text.SerialMsg;

/**
 * Writes a {@link PoseRecording} as a PARSL file (PARSL.md §12): a robot with the recorded group,
 * a gait-table automaton {@code rec_G} with one row per pose, a behavior {@code play_G} that plays
 * it once on that group, and a main that runs the behavior, so the file runs on its own and can
 * be {@code <include>}d to play the automaton on other groups with other periods and phases.
 * Row i's time is the recorded interval before pose i; the first row (the move from wherever the
 * robot is, or the wrap from the last pose when cycling) takes the mean recorded interval, or
 * 1 s for a single pose. Times are rounded to the default tick (0.01 s) so that at the default tick
 * every pose is reached exactly on a tick. The file is replaced atomically, so a crash leaves the
 * previous version.
 */
public final class RecordingWriter {
    /** Row times are multiples of this (the default tick); also the shortest row, as a zero would skip the pose. */
    public static final double RESOLUTION = 0.01;

    private RecordingWriter() {
    }

    /** The duration of each row, seconds. */
    public static double[] rowTimes(PoseRecording r) {
        int n = r.size();
        double[] t = new double[n];
        double sum = 0;
        for (int i = 1; i < n; i++) {
            t[i] = Math.max(RESOLUTION, roundTick(r.interval(i)));
            sum += t[i];
        }
        t[0] = n > 1 ? Math.max(RESOLUTION, roundTick(sum / (n - 1))) : 1.0;
        return t;
    }

    /** The PARSL text of a recording with at least one pose; {@code origin} goes into a comment. */
    public static String toParsl(PoseRecording r, String origin) {
        return toParsl(r, origin, 1, false);
    }

    /**
     * The PARSL text of a recording played {@code rate} times as fast as recorded (the instance's
     * {@code period} is the recorded cycle divided by {@code rate}; none is written at rate 1),
     * once or, when {@code loop}, until stopped (no {@code cycles}). The IDE's pose playback runs it.
     */
    public static String toParsl(PoseRecording r, String origin, double rate, boolean loop) {
        if (!(rate > 0) || Double.isInfinite(rate)) {
            throw new IllegalArgumentException(SerialMsg.REC_RATE.text(rate));
        }
        if (r.size() == 0) {
            throw new IllegalArgumentException(SerialMsg.REC_NO_POSES.text());
        }
        String g = r.group();
        StringBuilder ids = new StringBuilder();
        for (int id : r.modules()) {
            ids.append(ids.length() == 0 ? "" : ", ").append(id);
        }
        double[] t = rowTimes(r);
        StringBuilder times = new StringBuilder();
        List<String> rows = new ArrayList<>();
        for (int i = 0; i < r.size(); i++) {
            times.append(i == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.2f", t[i]));
            StringBuilder row = new StringBuilder();
            double[] p = r.pose(i);
            for (int k = 0; k < p.length; k++) {
                row.append(k == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.2f", p[k] == 0 ? 0.0 : p[k]));
            }
            rows.add(row.toString());
        }
        double cycle = 0;
        for (double ti : t) {
            cycle += ti;
        }
        ElementWriter instance = ElementWriter.tag("rec_" + g).attr("group", g);
        if (rate != 1) {
            instance.attr("period", String.format(Locale.ROOT, "%.4f", cycle / rate));
        }
        if (!loop) {
            instance.attr("cycles", "1");
        }
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                + "<!-- Pose recording (PARSL.md section 12): " + r.size() + " poses of group " + g + " (modules "
                + ids + ")" + comment(origin) + ".\n"
                + "     rec_" + g + " holds one row per pose; row times are the intervals between captures.\n"
                + "     play_" + g + " plays it " + (loop ? "over and over" : "once") + "; include this file to play rec_" + g
                + " on other groups. -->\n"
                + ElementWriter.tag("program").lines("", List.of(
                        ElementWriter.tag("robot").lines("  ", List.of(ElementWriter.tag("structure").lines("    ",
                                List.of(ElementWriter.tag(g).attr("elements", ids.toString()).empty())))),
                        ElementWriter.tag("automata").lines("  ", List.of(ElementWriter.tag("rec_" + g)
                                .attr("times", times.toString()).lines("    ", rows))),
                        ElementWriter.tag("behaviors").lines("  ", List.of(ElementWriter.tag("play_" + g)
                                .lines("    ", List.of(instance.empty())))),
                        ElementWriter.tag("main").lines("  ", List.of(ElementWriter.tag("play_" + g).empty()))))
                + "\n";
    }

    private static String comment(String origin) {
        String safe = origin == null ? "" : origin.replace("--", "- -").replace("<", "(").replace(">", ")");
        return safe.isEmpty() ? "" : ", " + safe;
    }

    private static double roundTick(double v) {
        return Math.round(v / RESOLUTION) * RESOLUTION;
    }
}
