package org.parpe.core.load;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.xml.XText;

/** Splitting of PARSL lists: commas at the top level (not inside parentheses or strings). */
final class ListItem {
    private ListItem() {
    }

    /** The items of {@code text}, trimmed, each keeping its place; empty items are kept (as empty). */
    static List<XText> split(XText text, char separator) {
        String s = text.value();
        List<XText> out = new ArrayList<>();
        int depth = 0;
        boolean string = false;
        int start = 0;
        for (int i = 0; i <= s.length(); i++) {
            char c = i < s.length() ? s.charAt(i) : separator;
            if (c == '"') {
                string = !string;
            } else if (!string && c == '(') {
                depth++;
            } else if (!string && c == ')') {
                depth--;
            } else if (i == s.length() || !string && depth <= 0 && c == separator) {
                out.add(trim(text, start, i));
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
