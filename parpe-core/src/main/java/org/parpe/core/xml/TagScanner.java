package org.parpe.core.xml;

import org.parpe.core.diag.SourceSpan;


/** Finds attribute values and text in the raw file text, decoding entities with positions. */
final class TagScanner {
    private TagScanner() {
    }

    /** Builds an element from the start tag at {@code offset} (the {@code <}). */
    static XElement element(SourceText src, int offset, String name) {
        String s = src.text();
        int i = offset + 1;
        XElement e = new XElement(name, src.pos(i), src, offset);
        i += name.length();
        while (i < s.length()) {
            i = skipSpace(s, i);
            char c = s.charAt(i);
            if (c == '>' || c == '/') {
                e.tagEnd(i);
                break;
            }
            int nameStart = i;
            while (i < s.length() && !Character.isWhitespace(s.charAt(i)) && s.charAt(i) != '=') {
                i++;
            }
            String attrName = s.substring(nameStart, i);
            i = skipSpace(s, i) + 1; // '='
            i = skipSpace(s, i);
            char quote = s.charAt(i);
            int valueStart = i + 1;
            int valueEnd = s.indexOf(quote, valueStart);
            XText value = decode(src, valueStart, valueEnd, true);
            e.addAttribute(new XElement.XAttr(attrName, src.pos(nameStart), value),
                    new SourceSpan.Range(valueStart, valueEnd - valueStart));
            i = valueEnd + 1;
        }
        return e;
    }

    /** Text content starting at {@code offset}; {@code expected} is what the parser decoded. */
    static XText text(SourceText src, int offset, String expected) {
        String s = src.text();
        int end = s.indexOf('<', offset);
        XText t = decode(src, offset, end < 0 ? s.length() : end, false);
        if (t.value().equals(expected)) {
            return t;
        }
        // CDATA or other constructs: keep the parser's text, placed at the start.
        int[] offsets = new int[expected.length()];
        java.util.Arrays.fill(offsets, offset);
        return new XText(expected, offset, offsets, offset, src);
    }

    private static int skipSpace(String s, int i) {
        while (i < s.length() && Character.isWhitespace(s.charAt(i))) {
            i++;
        }
        return i;
    }

    /** Decodes entity and character references; in attributes, white space becomes a space. */
    private static XText decode(SourceText src, int from, int to, boolean attribute) {
        String s = src.text();
        StringBuilder out = new StringBuilder(to - from);
        int[] offsets = null; // made only once a character is not at from + its index
        for (int i = from; i < to; i++) {
            char c = s.charAt(i);
            int at = i;
            if (c == '&') {
                int semi = s.indexOf(';', i);
                String ent = s.substring(i + 1, semi);
                c = entity(ent);
                i = semi;
            } else if (c == '\r') {
                if (i + 1 < to && s.charAt(i + 1) == '\n') {
                    continue;
                }
                c = '\n';
            }
            if (attribute && (c == '\n' || c == '\t')) {
                c = ' ';
            }
            int n = out.length();
            if (offsets == null && at != from + n) {
                offsets = new int[to - from];
                for (int k = 0; k < n; k++) {
                    offsets[k] = from + k;
                }
            }
            if (offsets != null) {
                offsets[n] = at;
            }
            out.append(c);
        }
        int[] exact = offsets == null ? null : java.util.Arrays.copyOf(offsets, out.length());
        return new XText(out.toString(), from, exact, to, src);
    }

    private static char entity(String ent) {
        switch (ent) {
            case "lt": return '<';
            case "gt": return '>';
            case "amp": return '&';
            case "quot": return '"';
            case "apos": return '\'';
            default:
                if (ent.startsWith("#x")) {
                    return (char) Integer.parseInt(ent.substring(2), 16);
                }
                return (char) Integer.parseInt(ent.substring(1));
        }
    }

}
