package org.parpe.sim.bridge;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayDeque;
import java.util.Deque;

/**
 * The XML text of an export: elements with attributes, two-space indentation, numbers with at
 * most nine significant digits and no exponent, so the same robot gives the same bytes.
 */
final class XmlOut {
    private final StringBuilder out = new StringBuilder("<?xml version=\"1.0\"?>\n");
    private final Deque<String> open = new ArrayDeque<>();
    private boolean tagOpen;

    /** Adds a comment line. */
    XmlOut comment(String text) {
        close();
        indent().append("<!-- ").append(text.replace("--", "- -")).append(" -->\n");
        return this;
    }

    /** Opens element {@code name}; attributes follow with {@link #attr}. */
    XmlOut start(String name) {
        close();
        indent().append('<').append(name);
        open.push(name);
        tagOpen = true;
        return this;
    }

    XmlOut attr(String name, String value) {
        out.append(' ').append(name).append("=\"").append(escape(value)).append('"');
        return this;
    }

    XmlOut attr(String name, double... values) {
        return attr(name, nums(values));
    }

    /** An element with text content and no attributes: {@code <name>text</name>}. */
    XmlOut text(String name, String text) {
        close();
        indent().append('<').append(name).append('>').append(escape(text)).append("</").append(name).append(">\n");
        return this;
    }

    XmlOut text(String name, double... values) {
        return text(name, nums(values));
    }

    /** Closes the innermost open element. */
    XmlOut end() {
        String name = open.pop();
        if (tagOpen) {
            out.append("/>\n");
            tagOpen = false;
        } else {
            indent().append("</").append(name).append(">\n");
        }
        return this;
    }

    @Override
    public String toString() {
        while (!open.isEmpty()) {
            end();
        }
        return out.toString();
    }

    private void close() {
        if (tagOpen) {
            out.append(">\n");
            tagOpen = false;
        }
    }

    private StringBuilder indent() {
        return out.append("  ".repeat(open.size()));
    }

    /** Numbers separated by spaces. */
    static String nums(double... values) {
        StringBuilder b = new StringBuilder();
        for (double v : values) {
            if (b.length() > 0) {
                b.append(' ');
            }
            b.append(num(v));
        }
        return b.toString();
    }

    /** A number with at most nine significant digits, plain, {@code 0} for tiny values and −0. */
    static String num(double v) {
        if (Math.abs(v) < 1e-12) {
            return "0";
        }
        return new BigDecimal(v).round(new MathContext(9)).stripTrailingZeros().toPlainString();
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
