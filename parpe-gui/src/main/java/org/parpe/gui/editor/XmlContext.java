package org.parpe.gui.editor;

import java.util.ArrayList;
import java.util.List;

/**
 * Where the caret is in a PARSL document, as far as completion cares: the chain of open
 * elements, and whether the caret is in an element name, in an attribute name, or inside an
 * attribute value. Computed by a small forgiving scan of the text before the caret, so it
 * works on documents that do not parse.
 *
 * @param path      names of the open elements, outermost first (the tag being typed excluded)
 * @param kind      what the caret is in
 * @param element   the element of the tag being typed (for attribute names and values)
 * @param attribute the attribute whose value the caret is in
 * @param prefix    the partial word before the caret
 */
public record XmlContext(List<String> path, Kind kind, String element, String attribute, String prefix) {

    /** What the caret is in. */
    public enum Kind { ELEMENT_NAME, ATTRIBUTE_NAME, ATTRIBUTE_VALUE, TEXT }

    /** The context at {@code offset} of {@code text}. */
    public static XmlContext at(String text, int offset) {
        List<String> path = new ArrayList<>();
        int i = 0;
        int tagStart = -1;
        while (i < offset) {
            if (text.startsWith("<!--", i)) {
                int end = text.indexOf("-->", i + 4);
                if (end < 0 || end + 3 > offset) {
                    return new XmlContext(path, Kind.TEXT, "", "", "");
                }
                i = end + 3;
                continue;
            }
            char c = text.charAt(i);
            if (c == '<') {
                int end = tagEnd(text, i, offset);
                if (end < 0) {
                    tagStart = i;
                    break;
                }
                applyTag(text.substring(i, end + 1), path);
                i = end + 1;
                continue;
            }
            i++;
        }
        if (tagStart < 0) {
            return new XmlContext(path, Kind.TEXT, "", "", wordBefore(text, offset));
        }
        return inTag(path, text.substring(tagStart, offset));
    }

    /** The index of the {@code >} closing the tag at {@code start}, or −1 if not before {@code limit}. */
    private static int tagEnd(String text, int start, int limit) {
        char quote = 0;
        for (int j = start + 1; j < limit; j++) {
            char c = text.charAt(j);
            if (quote != 0) {
                if (c == quote) {
                    quote = 0;
                }
            } else if (c == '"' || c == '\'') {
                quote = c;
            } else if (c == '>') {
                return j;
            }
        }
        return -1;
    }

    private static void applyTag(String tag, List<String> path) {
        if (tag.startsWith("<?") || tag.startsWith("<!")) {
            return;
        }
        if (tag.startsWith("</")) {
            String name = name(tag, 2);
            int k = path.lastIndexOf(name);
            if (k >= 0) {
                path.subList(k, path.size()).clear();
            }
            return;
        }
        if (!tag.endsWith("/>")) {
            path.add(name(tag, 1));
        }
    }

    private static XmlContext inTag(List<String> path, String partial) {
        int nameEnd = 1;
        while (nameEnd < partial.length() && XmlScanners.isNameChar(partial.charAt(nameEnd))) {
            nameEnd++;
        }
        String element = partial.substring(1, nameEnd);
        if (nameEnd == partial.length()) {
            return new XmlContext(path, Kind.ELEMENT_NAME, "", "", element.startsWith("/") ? "" : element);
        }
        int quotes = 0;
        int lastQuote = -1;
        for (int j = nameEnd; j < partial.length(); j++) {
            if (partial.charAt(j) == '"') {
                quotes++;
                lastQuote = j;
            }
        }
        if (quotes % 2 == 1) {
            String before = partial.substring(0, lastQuote).replaceAll("\\s*=\\s*$", "");
            String attr = wordBefore(before, before.length());
            return new XmlContext(path, Kind.ATTRIBUTE_VALUE, element, attr, valuePrefix(partial.substring(lastQuote + 1)));
        }
        return new XmlContext(path, Kind.ATTRIBUTE_NAME, element, "", wordBefore(partial, partial.length()));
    }

    /**
     * The last list item or identifier being typed in a value, {@code $} included; a group's
     * {@code !} is not a name character, so {@code !le} gives {@code le}.
     */
    private static String valuePrefix(String value) {
        int j = value.length();
        while (j > 0 && (XmlScanners.isNameChar(value.charAt(j - 1)) || value.charAt(j - 1) == '$')) {
            j--;
        }
        return value.substring(j);
    }

    private static String wordBefore(String text, int offset) {
        int j = offset;
        while (j > 0 && XmlScanners.isNameChar(text.charAt(j - 1))) {
            j--;
        }
        return text.substring(j, offset);
    }

    private static String name(String tag, int from) {
        int j = from;
        while (j < tag.length() && XmlScanners.isNameChar(tag.charAt(j))) {
            j++;
        }
        return tag.substring(from, j);
    }

    /** The enclosing element's name, or empty at the top. */
    public String parent() {
        return path.isEmpty() ? "" : path.get(path.size() - 1);
    }

    /** The element {@code depth} levels up from the caret (0: the parent). */
    public String ancestor(int depth) {
        int k = path.size() - 1 - depth;
        return k >= 0 ? path.get(k) : "";
    }
}
