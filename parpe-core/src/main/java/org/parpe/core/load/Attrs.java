package org.parpe.core.load;

import java.util.List;
import java.util.regex.Pattern;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.expr.Names;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XText;

/** Shape checks of elements: allowed attributes, required ones, text and children. */
final class Attrs {
    private static final Pattern NAME = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

    private Attrs() {
    }

    /** Reports every attribute of {@code e} that is not in {@code allowed}. */
    static void allow(XElement e, DiagnosticSink d, List<String> allowed) {
        for (XElement.XAttr a : e.attributes().values()) {
            if (!allowed.contains(a.name())) {
                Message hint = Names.suggest(a.name(), allowed);
                if (hint.equals(Message.EMPTY)) {
                    hint = allowed.isEmpty() ? Message.of(Msg.TAKES_NO_ATTRIBUTES, e.name())
                            : Message.of(Msg.ALLOWED_ATTRIBUTES, String.join(", ", allowed));
                }
                d.error(a.pos(), Msg.UNKNOWN_ATTRIBUTE, a.name(), e.name(), hint);
            }
        }
    }

    /** The value of a required attribute, or {@code null} after reporting it missing. */
    static XText require(XElement e, String name, DiagnosticSink d) {
        XElement.XAttr a = e.attr(name);
        if (a == null) {
            d.error(e.pos(), Msg.NEEDS_ATTRIBUTE, e.name(), name);
            return null;
        }
        return a.value();
    }

    /** The value of an optional attribute, or {@code null}. */
    static XText optional(XElement e, String name) {
        XElement.XAttr a = e.attr(name);
        return a == null ? null : a.value();
    }

    /** Reports text inside {@code e}. */
    static void noText(XElement e, DiagnosticSink d) {
        for (XText t : e.texts()) {
            String v = t.value();
            int first = 0;
            while (first < v.length() && Character.isWhitespace(v.charAt(first))) {
                first++;
            }
            d.error(t.posAt(first), Msg.NO_TEXT_INSIDE, e.name());
        }
    }

    /** Reports child elements of {@code e}. */
    static void noChildren(XElement e, DiagnosticSink d) {
        for (XElement c : e.children()) {
            d.error(c.pos(), Msg.NO_ELEMENTS_INSIDE, e.name(), c.name());
        }
    }

    /** Checks a name (PARSL.md §1, §13 rule 10); returns whether it is usable. */
    static boolean validName(String name, String kind, org.parpe.core.diag.SourcePos pos, DiagnosticSink d) {
        if (!NAME.matcher(name).matches()) {
            d.error(pos, Msg.INVALID_NAME, name, Msg.kind(kind));
            return false;
        }
        if (Vocabulary.isReserved(name) && !(kind.equals("group") && name.equals("all"))) {
            d.error(pos, Msg.RESERVED_NAME, name, Msg.kind(kind));
            return false;
        }
        return true;
    }

    /** Whether {@code s} is a valid identifier. */
    static boolean isName(String s) {
        return NAME.matcher(s).matches();
    }
}
