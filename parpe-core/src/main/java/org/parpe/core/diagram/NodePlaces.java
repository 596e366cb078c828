package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.lang.Numbers;
import org.parpe.core.text.DiagramMsg;

/**
 * Where the user put the free nodes of a script's diagrams ({@link Workbench}): per view, per
 * element name, a point of the workbench (scene units from its top left corner, to 0.1). Layout only:
 * nothing in the script depends on it, so it is kept beside the script, never inside it. The
 * text form, one line per node after a header line, is what {@link #format()} writes and
 * {@link #parse} reads leniently:
 *
 * <pre>
 * parpe-layout 1
 * program idle 40 12
 * lanes crawl 262 12
 * </pre>
 *
 * Immutable.
 */
public final class NodePlaces {
    /** The first line of every layout file PARPE writes; a file without it is not ours. */
    public static final String HEADER = "parpe-layout 1";
    /** No places at all. */
    public static final NodePlaces NONE = new NodePlaces(Map.of());

    /** The places, by view and then by name, in the order written. */
    private final Map<String, Map<String, double[]>> views;

    private NodePlaces(Map<String, Map<String, double[]>> views) {
        this.views = views;
    }

    /**
     * What {@link #parse} read.
     *
     * @param places  the places read (none from a foreign text)
     * @param ours    whether the text is a PARPE layout (or empty): only such a file is written over
     * @param message one line saying what was not read and why, or {@code ""}
     */
    public record Read(NodePlaces places, boolean ours, String message) {
    }

    /** The point of {@code name} on {@code view}'s workbench, or {@code null} when it has none. */
    public double[] at(String view, String name) {
        double[] p = views.getOrDefault(view, Map.of()).get(name);
        return p == null ? null : p.clone();
    }

    /** The places of {@code view}, by name (copies). */
    public Map<String, double[]> of(String view) {
        Map<String, double[]> out = new LinkedHashMap<>();
        views.getOrDefault(view, Map.of()).forEach((k, v) -> out.put(k, v.clone()));
        return out;
    }

    /** These places with {@code name} of {@code view} at {@code x, y}. */
    public NodePlaces with(String view, String name, double x, double y) {
        check(view, "view");
        check(name, "name");
        Map<String, Map<String, double[]>> copy = copy();
        // to the 0.1 the file keeps: a place in memory is the place read back
        copy.computeIfAbsent(view, k -> new LinkedHashMap<>()).put(name, new double[] {tenth(x), tenth(y)});
        return new NodePlaces(copy);
    }

    /**
     * These places with only {@code names} kept on {@code view}: a node that is no longer free
     * (now in {@code <main>}, renamed or removed) loses its place, and gets a free one should it
     * come back.
     */
    public NodePlaces retain(String view, Collection<String> names) {
        Map<String, Map<String, double[]>> copy = copy();
        Map<String, double[]> v = copy.get(view);
        if (v != null) {
            v.keySet().retainAll(names);
            if (v.isEmpty()) {
                copy.remove(view);
            }
        }
        return new NodePlaces(copy);
    }

    /** Whether there is no place at all. */
    public boolean isEmpty() {
        return views.isEmpty();
    }

    /** The text form: the header, then {@code VIEW NAME X Y} per node, coordinates to 0.1. */
    public String format() {
        StringBuilder s = new StringBuilder(HEADER).append('\n');
        views.forEach((view, names) -> names.forEach((name, p) -> s.append(view).append(' ').append(name).append(' ')
                .append(Numbers.format(tenth(p[0]))).append(' ').append(Numbers.format(tenth(p[1]))).append('\n')));
        return s.toString();
    }

    private static double tenth(double v) {
        return Math.round(v * 10) / 10.0;
    }

    /**
     * Reads the text form of {@code file} (named in messages). Never throws: a text whose first
     * line is not {@link #HEADER} is foreign (no places, not ours); a line that is not
     * {@code VIEW NAME X Y} with finite numbers is left out, and the message names the first
     * such line as {@code FILE:LINE} and how many there were.
     */
    public static Read parse(String file, String text) {
        String[] lines = text.split("\r?\n", -1);
        if (text.isBlank()) {
            return new Read(NONE, true, "");
        }
        if (!lines[0].strip().equals(HEADER)) {
            return new Read(NONE, false, DiagramMsg.LAYOUT_FOREIGN.text(file, HEADER));
        }
        Map<String, Map<String, double[]>> views = new LinkedHashMap<>();
        List<String> bad = new ArrayList<>();
        for (int i = 1; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] w = line.split("\\s+");
            Double x = w.length == 4 ? Numbers.parsePlain(w[2]) : null;
            Double y = w.length == 4 ? Numbers.parsePlain(w[3]) : null;
            if (x == null || y == null || !Double.isFinite(x) || !Double.isFinite(y)) {
                bad.add(DiagramMsg.LAYOUT_BAD_LINE.text(file + ":" + (i + 1), shorten(line)));
                continue;
            }
            views.computeIfAbsent(w[0], k -> new LinkedHashMap<>()).put(w[1], new double[] {x, y});
        }
        String message = bad.isEmpty() ? "" : (bad.size() > 1 ? DiagramMsg.LAYOUT_BAD_LINES.text(bad.get(0), bad.size() - 1)
                : DiagramMsg.LAYOUT_BAD.text(bad.get(0)));
        return new Read(new NodePlaces(views), true, message);
    }

    private static String shorten(String s) {
        return s.length() > 40 ? s.substring(0, 39) + "…" : s;
    }

    private static void check(String word, String what) {
        if (word.isEmpty() || word.chars().anyMatch(Character::isWhitespace)) {
            throw new IllegalArgumentException("a layout " + what + " is one word, got '" + word + "'");
        }
    }

    private Map<String, Map<String, double[]>> copy() {
        Map<String, Map<String, double[]>> copy = new LinkedHashMap<>();
        views.forEach((k, v) -> copy.put(k, new LinkedHashMap<>(v)));
        return copy;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof NodePlaces n && format().equals(n.format());
    }

    @Override
    public int hashCode() {
        return format().hashCode();
    }

    @Override
    public String toString() {
        return format();
    }
}
