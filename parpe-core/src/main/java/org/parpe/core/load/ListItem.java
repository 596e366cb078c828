package org.parpe.core.load;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.xml.XText;

/** Splitting of PARSL lists: commas at the top level (not inside parentheses or strings). */
public final class ListItem {
    private ListItem() {
    }

    /** The items of {@code text}, trimmed, each keeping its place; empty items are kept (as empty). */
    static List<XText> split(XText text, char separator) {
        List<XText> out = new ArrayList<>();
        for (int[] r : ranges(text.value(), 0, text.value().length(), separator)) {
            out.add(trim(text, r[0], r[1]));
        }
        return out;
    }

    /**
     * The ranges {@code [start, end)} of the items of {@code s[from, to)}, untrimmed, split at
     * {@code separator} where it is outside parentheses and strings, as the loader splits every
     * PARSL list (editors that rewrite one item use it to find the same items).
     */
    public static List<int[]> ranges(String s, int from, int to, char separator) {
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

    /** The part {@code [from, to)} of {@code text} without surrounding white space. */
    static XText trim(XText text, int from, int to) {
        String s = text.value();
        while (from < to && Character.isWhitespace(s.charAt(from))) {
            from++;
        }
        while (to > from && Character.isWhitespace(s.charAt(to - 1))) {
            to--;
        }
        return text.sub(from, to);
    }
}
