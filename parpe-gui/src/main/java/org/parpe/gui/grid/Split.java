package org.parpe.gui.grid;

import java.util.ArrayList;
import java.util.List;

/** Splitting at top-level separators, as the loader splits PARSL lists (not inside parentheses or strings). */
final class Split {
    private Split() {
    }

    /** The ranges {@code [start, end)} of the parts of {@code s[from, to)}. */
    static List<int[]> parts(String s, int from, int to, char separator) {
        List<int[]> out = new ArrayList<>();
        int depth = 0;
        boolean string = false;
        int start = from;
        for (int i = from; i <= to; i++) {
            char c = i < to ? s.charAt(i) : separator;
            if (c == '"') {
                string = !string;
            } else if (!string && c == '(') {
                depth++;
            } else if (!string && c == ')') {
                depth--;
            } else if (i == to || !string && depth <= 0 && c == separator) {
                out.add(new int[] {start, i});
                start = i + 1;
            }
        }
        return out;
    }

    /** The trimmed texts of the parts of {@code s}. */
    static List<String> texts(String s, char separator) {
        List<String> out = new ArrayList<>();
        for (int[] p : parts(s, 0, s.length(), separator)) {
            out.add(s.substring(p[0], p[1]).trim());
        }
        return out;
    }
}
