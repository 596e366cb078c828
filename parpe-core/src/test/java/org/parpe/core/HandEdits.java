package org.parpe.core;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Edits of a script made "by hand" on its text, for comparison with the diagram edit API: they
 * find elements from their line and column and attributes with regular expressions, and share
 * nothing with the spans or the edit API.
 */
final class HandEdits {
    private static final Pattern ATTR = Pattern.compile("\\s+([\\w.-]+)\\s*=\\s*(\"([^\"]*)\"|'([^']*)')");

    private HandEdits() {
    }

    /** The offset of 1-based {@code line}, {@code column}. */
    static int offset(String text, int line, int column) {
        int at = 0;
        for (int l = 1; l < line; l++) {
            at = text.indexOf('\n', at) + 1;
        }
        return at + column - 1;
    }

    /** The start tag whose name is at {@code line:column}: [start, end) and its attributes' matches. */
    record Tag(int start, int end, boolean empty, String name, List<int[]> values, List<String> names) {
    }

    static Tag tag(String text, int line, int column) {
        int nameAt = offset(text, line, column);
        int i = nameAt;
        while (!Character.isWhitespace(text.charAt(i)) && text.charAt(i) != '/' && text.charAt(i) != '>') {
            i++;
        }
        String name = text.substring(nameAt, i);
        Matcher m = ATTR.matcher(text);
        List<int[]> values = new ArrayList<>();
        List<String> names = new ArrayList<>();
        while (m.find(i) && m.start() == i) {
            int g = m.group(3) != null ? 3 : 4;
            values.add(new int[] {m.start(g), m.end(g)});
            names.add(m.group(1));
            i = m.end();
        }
        int close = text.indexOf('>', i);
        boolean empty = text.charAt(close - 1) == '/';
        return new Tag(nameAt - 1, close + 1, empty, name, values, names);
    }

    /** Where the element of the tag ends (after {@code />} or its end tag). */
    static int elementEnd(String text, Tag t) {
        if (t.empty) {
            return t.end;
        }
        Matcher m = Pattern.compile("</" + Pattern.quote(t.name) + "\\s*>").matcher(text);
        if (!m.find(t.end)) {
            throw new IllegalStateException("no end tag for " + t.name);
        }
        return m.end();
    }

    /** The value range of attribute {@code name}, or null. */
    static int[] value(Tag t, String name) {
        int k = t.names.indexOf(name);
        return k < 0 ? null : t.values.get(k);
    }

    static String replace(String text, int from, int to, String with) {
        return text.substring(0, from) + with + text.substring(to);
    }

    /** The items of a list value: top-level commas, outside (), [] and strings. */
    static List<int[]> items(String text, int from, int to) {
        List<int[]> out = new ArrayList<>();
        int depth = 0;
        boolean str = false;
        int start = from;
        for (int i = from; i < to; i++) {
            char c = text.charAt(i);
            if (c == '"') {
                str = !str;
            } else if (!str && (c == '(' || c == '[')) {
                depth++;
            } else if (!str && (c == ')' || c == ']')) {
                depth--;
            } else if (!str && depth == 0 && c == ',') {
                out.add(new int[] {start, i});
                start = i + 1;
            }
        }
        out.add(new int[] {start, to});
        return out;
    }

    /** Sets an attribute of the tag at line:column. */
    static String setAttribute(String text, int line, int column, String name, String value) {
        Tag t = tag(text, line, column);
        int[] v = value(t, name);
        if (v != null) {
            return replace(text, v[0], v[1], value);
        }
        int at = t.values.isEmpty() ? t.start + 1 + t.name.length() : t.values.get(t.values.size() - 1)[1] + 1;
        return replace(text, at, at, " " + name + "=\"" + value + "\"");
    }

    /** Replaces the duration (before any [exit]) of item {@code state} of the times attribute. */
    static String retime(String text, int line, int column, int state, int states, String duration) {
        Tag t = tag(text, line, column);
        int[] v = value(t, "times");
        if (v == null) {
            List<String> all = new ArrayList<>();
            for (int i = 0; i < states; i++) {
                all.add(i == state ? duration : "1");
            }
            return setAttribute(text, line, column, "times", String.join(", ", all));
        }
        int[] item = items(text, v[0], v[1]).get(state);
        String s = text.substring(item[0], item[1]);
        String lead = s.substring(0, s.length() - s.stripLeading().length());
        String body = s.strip();
        String tail = s.substring(lead.length() + body.length());
        int b = body.indexOf('[');
        String exit = b < 0 ? "" : body.substring(b);
        String gap = b < 0 ? "" : body.substring(0, b).substring(body.substring(0, b).stripTrailing().length());
        return replace(text, item[0], item[1], lead + duration + gap + exit + tail);
    }

    /** Moves entry {@code from} of main to {@code to}; entries are given by their line and column. */
    static String moveEntry(String text, List<int[]> entries, int from, int to) {
        List<String> pieces = new ArrayList<>();
        List<String> gaps = new ArrayList<>();
        int[] first = span(text, entries.get(0));
        String prefix = text.substring(0, first[0]);
        int prevEnd = -1;
        for (int[] e : entries) {
            int[] s = span(text, e);
            if (prevEnd >= 0) {
                gaps.add(text.substring(prevEnd, s[0]));
            }
            pieces.add(text.substring(s[0], s[1]));
            prevEnd = s[1];
        }
        String suffix = text.substring(prevEnd);
        pieces.add(to, pieces.remove(from));
        StringBuilder out = new StringBuilder(prefix);
        for (int i = 0; i < pieces.size(); i++) {
            out.append(pieces.get(i)).append(i < gaps.size() ? gaps.get(i) : "");
        }
        return out.append(suffix).toString();
    }

    private static int[] span(String text, int[] lineColumn) {
        Tag t = tag(text, lineColumn[0], lineColumn[1]);
        return new int[] {t.start, elementEnd(text, t)};
    }

    /** Appends a state name to states and, when times is written, a duration to times. */
    static String addState(String text, int line, int column, int states, String state, String duration) {
        Tag t = tag(text, line, column);
        int[] tv = value(t, "times");
        int[] sv = value(t, "states");
        java.util.TreeMap<Integer, String> inserts = new java.util.TreeMap<>();
        if (tv != null) {
            inserts.put(tv[0] + text.substring(tv[0], tv[1]).stripTrailing().length(), ", " + duration);
        } else if (!duration.equals("1")) {
            List<String> all = new ArrayList<>();
            for (int i = 0; i < states; i++) {
                all.add("1");
            }
            all.add(duration);
            inserts.put(t.values.get(t.values.size() - 1)[1] + 1, " times=\"" + String.join(", ", all) + "\"");
        }
        inserts.put(sv[0] + text.substring(sv[0], sv[1]).stripTrailing().length(), ", " + state);
        String out = text;
        for (var e : inserts.descendingMap().entrySet()) {
            out = replace(out, e.getKey(), e.getKey(), e.getValue());
        }
        return out;
    }
}
