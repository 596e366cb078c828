package org.parpe.core.edit;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.text.EditMsg;

/**
 * Edits of an element found by its {@link SourceSpan} (the place the loader gives every node,
 * in a script or a robot file): set an attribute, put a child first or last, remove the
 * element. The result is one {@link TextEdit}; only the characters that change are replaced, so
 * comments, order and layout stay as written. It works on any XML file the loader reads
 * with spans (scripts, robot configurations). {@code text} is always the text of the file the
 * node was read from, as it was when it was loaded. New children are written by
 * {@link ElementWriter}; whole sections by {@link SectionEdits}.
 */
public final class ScriptEdits {
    private ScriptEdits() {
    }

    /** The span of {@code node}, refused with a message when it was not read from a file's text. */
    public static SourceSpan span(SourcePos node) {
        if (node.span() == null) {
            throw new EditRefused(EditMsg.NOT_FROM_TEXT, node);
        }
        return node.span();
    }

    /**
     * Sets attribute {@code name} of the element of {@code node} to {@code value} (for example
     * an instance's {@code phase} or {@code offset}, an entry's {@code time}): its value is
     * replaced (escaped for the quote it is written in), or, when it is not written, the
     * attribute is added after the last one.
     */
    public static TextEdit setAttribute(String text, SourcePos node, String name, String value) {
        SourceSpan s = span(node);
        SourceSpan.Range r = s.value(name);
        if (r != null) {
            return TextEdit.of(r.offset(), r.length(), ElementWriter.attributeText(value, text.charAt(r.offset() - 1)));
        }
        return TextEdit.of(afterAttributes(text, s), 0, " " + name + "=\"" + ElementWriter.attributeText(value) + "\"");
    }

    /**
     * Removes attribute {@code name} of the element of {@code node} (a value back to its
     * default, as a robot builder writes orientation 0): the name, its value and the white space
     * before the name go; nothing when it is not written.
     */
    public static TextEdit removeAttribute(String text, SourcePos node, String name) {
        SourceSpan s = span(node);
        SourceSpan.Range r = s.value(name);
        if (r == null) {
            return new TextEdit(List.of());
        }
        int from = skipSpaceBack(text, r.offset() - 2); // on the '=' before the opening quote
        from = skipSpaceBack(text, from - 1) - name.length() + 1;
        while (from > s.start() && Character.isWhitespace(text.charAt(from - 1))) {
            from--;
        }
        return TextEdit.of(from, r.end() + 1 - from, "");
    }

    /** The offset of the last character at or before {@code at} that is not white space. */
    private static int skipSpaceBack(String text, int at) {
        while (Character.isWhitespace(text.charAt(at))) {
            at--;
        }
        return at;
    }

    /** Where a new attribute goes: after the last attribute's closing quote, or after the name. */
    private static int afterAttributes(String text, SourceSpan s) {
        int at = s.start() + 1;
        for (SourceSpan.Range r : s.values().values()) {
            at = Math.max(at, r.end() + 1);
        }
        if (at == s.start() + 1) {
            while (at < s.tagEnd() && !Character.isWhitespace(text.charAt(at))) {
                at++;
            }
        }
        return at;
    }

    /**
     * {@code element} as the last child of the element {@code parent} (named {@code tag}): after
     * {@code last} (its last child, or null when it has none) on a line of its own with that
     * child's indentation, else two spaces deeper than the parent (an empty-element parent gets
     * its end tag).
     */
    public static TextEdit appendChild(String text, SourceSpan parent, String tag, SourceSpan last, String element) {
        if (last != null) {
            return TextEdit.of(last.end(), 0, "\n" + ElementWriter.indent(text, last.start()) + element);
        }
        String indent = ElementWriter.indent(text, parent.start());
        if (parent.empty()) {
            return TextEdit.of(parent.tagEnd(), 2, ">\n" + indent + "  " + element + "\n" + indent + ElementWriter.close(tag));
        }
        int endTag = text.lastIndexOf("</", parent.end() - 1);
        int[] content = trim(text, parent.tagEnd() + 1, endTag);
        // content of white space only: just after the start tag, so the end tag keeps its line
        int at = content[0] == content[1] ? parent.tagEnd() + 1 : content[1];
        if (at == endTag) {
            return TextEdit.of(at, 0, "\n" + indent + "  " + element + "\n" + indent);
        }
        return TextEdit.of(at, 0, "\n" + indent + "  " + element);
    }

    /**
     * {@code element} as the first child of the (not empty) element {@code parent}, on a line
     * of its own just after the start tag, indented as {@code indent} (the parent's line's own
     * indentation, tabs included) plus two spaces.
     */
    public static TextEdit prependChild(String text, SourceSpan parent, String element) {
        int lineStart = text.lastIndexOf('\n', parent.start() - 1) + 1;
        int i = lineStart;
        while (i < parent.start() && (text.charAt(i) == ' ' || text.charAt(i) == '\t')) {
            i++;
        }
        return TextEdit.of(parent.tagEnd() + 1, 0, "\n" + text.substring(lineStart, i) + "  " + element);
    }

    /**
     * Renames the element {@code s}, now named {@code from}, to {@code to}: the name in its start
     * tag and, when it has one, in its end tag; its attributes and children stay.
     */
    public static List<Replacement> rename(String text, SourceSpan s, String from, String to) {
        List<Replacement> out = new ArrayList<>();
        out.add(new Replacement(s.start() + 1, from.length(), to));
        if (!s.empty()) {
            out.add(new Replacement(text.lastIndexOf("</", s.end() - 1) + 2, from.length(), to));
        }
        return out;
    }

    /** Removes the element {@code s}, with its line when it stands alone on it. */
    public static TextEdit removeElement(String text, SourceSpan s) {
        int from = s.start();
        int to = s.end();
        int lineStart = text.lastIndexOf('\n', from - 1) + 1;
        int lineEnd = text.indexOf('\n', to);
        if (text.substring(lineStart, from).isBlank() && lineEnd >= 0 && text.substring(to, lineEnd).isBlank()) {
            from = lineStart;
            to = lineEnd + 1;
        }
        return TextEdit.of(from, to - from, "");
    }

    /** {@code [from, to)} without the white space at either end. */
    public static int[] trim(String text, int from, int to) {
        while (from < to && Character.isWhitespace(text.charAt(from))) {
            from++;
        }
        while (to > from && Character.isWhitespace(text.charAt(to - 1))) {
            to--;
        }
        return new int[] {from, to};
    }
}
