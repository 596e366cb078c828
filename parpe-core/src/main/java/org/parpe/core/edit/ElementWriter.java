package org.parpe.core.edit;

import java.util.List;
import org.parpe.core.text.EditMsg;
import org.parpe.core.text.Msg;

/**
 * Writes one XML element of a script or robot file: its tag, its attributes (values escaped for
 * double quotes) and, for an element with children, its lines at an indentation. Every place
 * that writes PARSL element text (the diagrams' and palette's edits, the gait-table expansion,
 * the Pose panel, the sweep, the recorder, the printer) builds it here, so a value is escaped one
 * way and a child is indented one way.
 *
 * <pre>{@code
 * ElementWriter.tag("walk").attr("group", "legs").empty()        // <walk group="legs"/>
 * ElementWriter.tag("t").attr("times", "1, 2").lines("  ", rows) // <t times="1, 2">\n    row…\n  </t>
 * }</pre>
 */
public final class ElementWriter {
    private final String tag;
    private final StringBuilder head;

    private ElementWriter(String tag) {
        this.tag = tag;
        this.head = new StringBuilder("<").append(tag);
    }

    /** An element named {@code tag}, with no attributes yet. */
    public static ElementWriter tag(String tag) {
        return new ElementWriter(tag);
    }

    /** Adds attribute {@code name} with {@code value} (escaped, written between double quotes). */
    public ElementWriter attr(String name, String value) {
        head.append(' ').append(name).append("=\"").append(attributeText(value)).append('"');
        return this;
    }

    /** Adds attribute {@code name} when {@code value} is neither null nor blank. */
    public ElementWriter attrIfGiven(String name, String value) {
        return value == null || value.isBlank() ? this : attr(name, value);
    }

    /** The element as an empty-element tag: {@code <tag a="v"/>}. */
    public String empty() {
        return head + "/>";
    }

    /** The start tag alone: {@code <tag a="v">}. */
    public String open() {
        return head + ">";
    }

    /** The end tag of {@code tag}. */
    public static String close(String tag) {
        return "</" + tag + ">";
    }

    /**
     * The element holding {@code lines}, its first line at {@code indent} (not written: the
     * caller puts it there), each child line two spaces deeper, the end tag at {@code indent}.
     */
    public String lines(String indent, List<String> lines) {
        StringBuilder e = new StringBuilder(open());
        for (String line : lines) {
            e.append('\n').append(indent).append("  ").append(line);
        }
        return e.append('\n').append(indent).append(close(tag)).toString();
    }

    /** {@code value} as character data: {@code & < >} as entities. */
    public static String text(String value) {
        return value.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    /** {@code value} written inside a double-quoted attribute: {@code & < > "} as entities. */
    public static String attributeText(String value) {
        return text(value).replace("\"", "&quot;");
    }

    /** {@code value} written between {@code quote}s (a double or a single quote). */
    public static String attributeText(String value, char quote) {
        String s = attributeText(value);
        return quote == '\'' ? s.replace("&quot;", "\"").replace("'", "&apos;") : s;
    }

    /**
     * {@code name} when it can be an element's name in a script (a letter or {@code _} first,
     * then letters, digits, {@code _ . -}); else refused with a message naming it and
     * {@code what} it was to name.
     */
    public static String name(String name, String what) {
        boolean ok = !name.isEmpty() && nameStart(name.charAt(0));
        for (int i = 1; ok && i < name.length(); i++) {
            char c = name.charAt(i);
            ok = nameStart(c) || isAsciiDigit(c) || c == '.' || c == '-';
        }
        if (!ok) {
            throw new EditRefused(EditMsg.BAD_NAME, name, Msg.kind(what));
        }
        return name;
    }

    private static boolean nameStart(char c) {
        return c >= 'A' && c <= 'Z' || c >= 'a' && c <= 'z' || c == '_';
    }

    private static boolean isAsciiDigit(char c) {
        return c >= '0' && c <= '9';
    }

    /** The spaces before {@code offset} on its line when only white space is there, else none. */
    public static String indent(String text, int offset) {
        int lineStart = text.lastIndexOf('\n', offset - 1) + 1;
        String before = text.substring(lineStart, offset);
        return before.isBlank() ? before : "";
    }

    /** Each line of {@code body} (lines ending in {@code \n}) prefixed with {@code indent}, each ending in {@code \n}. */
    public static String indentLines(String body, String indent) {
        StringBuilder b = new StringBuilder();
        for (String line : body.split("\n")) {
            b.append(indent).append(line).append('\n');
        }
        return b.toString();
    }
}
