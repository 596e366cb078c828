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
        // elements of the same name may nest (<if> in <if>): count them
        Matcher m = Pattern.compile("<(/?)" + Pattern.quote(t.name) + "(?=[\\s/>])[^>]*?(/?)>").matcher(text);
        int depth = 1;
        int at = t.end;
        while (m.find(at)) {
            at = m.end();
            if (!m.group(1).isEmpty()) {
                depth--;
                if (depth == 0) {
                    return m.end();
                }
            } else if (m.group(2).isEmpty()) {
                depth++;
            }
        }
        throw new IllegalStateException("no end tag for " + t.name);
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
    /** The items of attribute {@code name} of a tag, as [start, end) without spaces around them. */
    private static List<int[]> trimmedItems(String text, Tag t, String name) {
        int[] v = value(t, name);
        if (v == null) {
            return null;
        }
        List<int[]> out = new ArrayList<>();
        for (int[] item : items(text, v[0], v[1])) {
            String s = text.substring(item[0], item[1]);
            int lead = s.length() - s.stripLeading().length();
            out.add(new int[] {item[0] + lead, item[0] + lead + s.strip().length()});
        }
        return out;
    }

    /** Rewrites states and times with item {@code state} and its comma left out. */
    static String removeState(String text, int line, int column, int state) {
        Tag t = tag(text, line, column);
        String out = text;
        // times comes after states in no particular order: edit the later attribute first
        List<String> attrs = new ArrayList<>(List.of("states", "times"));
        attrs.removeIf(a -> value(t, a) == null);
        attrs.sort((x, y) -> Integer.compare(value(t, y)[0], value(t, x)[0]));
        for (String a : attrs) {
            List<int[]> it = trimmedItems(text, t, a);
            int from = state == 0 ? it.get(0)[0] : it.get(state - 1)[1];
            int to = state == 0 ? it.get(1)[0] : it.get(state)[1];
            out = replace(out, from, to, "");
        }
        return out;
    }

    /** Rewrites states and times with item {@code from} moved to place {@code to}. */
    static String moveState(String text, int line, int column, int from, int to) {
        Tag t = tag(text, line, column);
        List<String> attrs = new ArrayList<>(List.of("states", "times"));
        attrs.removeIf(a -> value(t, a) == null);
        attrs.sort((x, y) -> Integer.compare(value(t, y)[0], value(t, x)[0]));
        String out = text;
        for (String a : attrs) {
            List<int[]> it = trimmedItems(text, t, a);
            List<String> bodies = new ArrayList<>();
            it.forEach(r -> bodies.add(text.substring(r[0], r[1])));
            bodies.add(to, bodies.remove(from));
            for (int k = it.size() - 1; k >= 0; k--) {
                out = replace(out, it.get(k)[0], it.get(k)[1], bodies.get(k));
            }
        }
        return out;
    }

    /** Sets item {@code state}'s [exit] of times (removes it when {@code exit} is empty). */
    static String setExit(String text, int line, int column, int state, int states, String exit) {
        Tag t = tag(text, line, column);
        String cond = exit.isEmpty() ? "" : "[" + exit + "]";
        if (value(t, "times") == null) {
            if (cond.isEmpty()) {
                return text;
            }
            List<String> all = new ArrayList<>();
            for (int i = 0; i < states; i++) {
                all.add(i == state ? "1" + cond : "1");
            }
            return setAttribute(text, line, column, "times", String.join(", ", all));
        }
        int[] item = trimmedItems(text, t, "times").get(state);
        String body = text.substring(item[0], item[1]);
        int b = body.indexOf('[');
        String duration = b < 0 ? body : body.substring(0, b).stripTrailing();
        return replace(text, item[0], item[1], duration + cond);
    }

    /**
     * Adds {@code element} as the last child of the element at line:column: after the child
     * at {@code last} (line, column; null when there is none) with its indentation.
     */
    static String appendChild(String text, int line, int column, int[] last, String element) {
        Tag t = tag(text, line, column);
        if (last != null) {
            Tag c = tag(text, last[0], last[1]);
            int end = elementEnd(text, c);
            return replace(text, end, end, "\n" + indentOf(text, c.start) + element);
        }
        String indent = indentOf(text, t.start);
        if (t.empty) {
            return replace(text, t.end - 2, t.end, ">\n" + indent + "  " + element + "\n" + indent + "</" + t.name + ">");
        }
        int endTag = elementEnd(text, t) - ("</" + t.name + ">").length();
        int at = t.end + text.substring(t.end, endTag).stripTrailing().length();
        return replace(text, at, at, "\n" + indent + "  " + element);
    }

    static String indentOf(String text, int at) {
        int lineStart = text.lastIndexOf('\n', at - 1) + 1;
        return text.substring(lineStart, at).isBlank() ? text.substring(lineStart, at) : "";
    }
}
