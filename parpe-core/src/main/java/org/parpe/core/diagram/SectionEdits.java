package org.parpe.core.diagram;

import java.util.List;
import java.util.function.Function;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.xml.SourceText;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XmlReader;

/**
 * Edits that let a script be built from an empty file: the first robot (a chain of modules in
 * one group), and a new element put into its section (PARSL.md §1), which is written when the
 * file does not have it yet. A new section goes after the last section the file has that comes
 * before it in {@link #ORDER} (the order of the examples), with the indentation of the root's
 * other children; a new element goes after the section's last child with that one's
 * indentation, or two spaces deeper than the section. Nothing else of the text changes.
 */
public final class SectionEdits {
    /** Where a new section goes: after the last of those before it in this list that the file has. */
    public static final List<String> ORDER = List.of("robot", "parameters", "controls", "main", "behaviors", "automata",
            "states");

    /** The most modules {@link #startRobot} writes (a chain is a range, so the text stays one line). */
    public static final int MAX_MODULES = 10_000;

    private SectionEdits() {
    }

    /**
     * Whether {@code text} holds no element: only white space, an XML declaration, comments or
     * processing instructions (the file of a student who has not started yet).
     */
    public static boolean blank(String text) {
        return XmlReader.noElement(text);
    }

    /**
     * Starts a robot in a {@link #blank} text: {@code <program>} with a {@code <robot>} whose
     * structure is group {@code group} of modules {@code 0..modules-1} (a chain), written after
     * what the text holds (its declaration and comments stay).
     */
    public static TextEdit startRobot(String text, String group, int modules) {
        if (!blank(text)) {
            throw new IllegalArgumentException("the file has a script already; a robot is started only in an empty file");
        }
        BehaviorEdits.name(group, "group");
        if (modules < 1 || modules > MAX_MODULES) {
            throw new IllegalArgumentException("a robot has 1 to " + MAX_MODULES + " modules, not " + modules);
        }
        int end = text.length();
        while (end > 0 && Character.isWhitespace(text.charAt(end - 1))) {
            end--;
        }
        String elements = modules == 1 ? "0" : "0.." + (modules - 1);
        String program = String.join("\n", "<program>", "  <robot>", "    <structure>",
                "      <" + group + " elements=\"" + elements + "\"/>", "    </structure>", "  </robot>", "</program>", "");
        return TextEdit.of(end, text.length() - end, (end == 0 ? "" : "\n") + program);
    }

    /**
     * Puts a new element as the last child of the element at {@code path} below the root (a
     * section, or {@code "robot", "structure"}), writing whichever of them the file lacks.
     * {@code element} gives the element's text for the indentation of its first line (its
     * further lines carry that indentation themselves).
     */
    static TextEdit add(String text, String file, Function<String, String> element, String... path) {
        DiagnosticList diags = new DiagnosticList();
        XElement parent = XmlReader.read(new SourceText(file, text), diags);
        if (parent == null) {
            throw new IllegalArgumentException("the script is not well-formed XML; mend it first (see Problems)");
        }
        for (int level = 0; level < path.length; level++) {
            XElement child = child(parent, path[level]);
            if (child == null) {
                return write(text, parent, level, element, path);
            }
            if (child.attr("file") != null) {
                throw new IllegalArgumentException("<" + path[level] + "> is read from " + child.attr("file").value().value()
                        + "; add to it there");
            }
            parent = child;
        }
        List<XElement> kids = parent.children();
        SourceSpan ps = parent.span();
        if (!kids.isEmpty()) {
            SourceSpan last = kids.get(kids.size() - 1).span();
            return TextEdit.of(last.end(), 0, "\n" + BehaviorEdits.indent(text, last.start())
                    + element.apply(BehaviorEdits.indent(text, last.start())));
        }
        String inner = BehaviorEdits.indent(text, ps.start()) + "  ";
        return BehaviorEdits.appendChild(text, ps, parent.name(), null, element.apply(inner));
    }

    /**
     * Writes the elements {@code path[level..]} that {@code parent} lacks, holding the new element:
     * a new section after the section it follows in {@link #ORDER} (or before the first one),
     * indented as that one; a new element of a section as the section's last child.
     */
    private static TextEdit write(String text, XElement parent, int level, Function<String, String> element,
                                  String... path) {
        List<XElement> kids = parent.children();
        XElement before = null;
        if (level == 0) {
            int rank = ORDER.indexOf(path[0]);
            for (XElement k : kids) {
                int r = ORDER.indexOf(k.name());
                if (r >= 0 && r < rank) {
                    before = k;
                }
            }
        } else if (!kids.isEmpty()) {
            before = kids.get(kids.size() - 1);
        }
        XElement like = before != null ? before : kids.isEmpty() ? null : kids.get(0);
        String indent = like == null ? BehaviorEdits.indent(text, parent.span().start()) + "  "
                : BehaviorEdits.indent(text, like.span().start());
        StringBuilder open = new StringBuilder();
        StringBuilder close = new StringBuilder();
        String at = indent;
        for (int k = level; k < path.length; k++) {
            open.append(k == level ? "" : "\n" + at).append('<').append(path[k]).append('>');
            close.insert(0, "\n" + at + "</" + path[k] + ">");
            at += "  ";
        }
        String nested = open + "\n" + at + element.apply(at) + close;
        if (before != null) {
            return TextEdit.of(before.span().end(), 0, "\n" + indent + nested);
        }
        if (like != null) {
            return TextEdit.of(like.span().start(), 0, nested + "\n" + indent);
        }
        return BehaviorEdits.appendChild(text, parent.span(), parent.name(), null, nested);
    }

    private static XElement child(XElement parent, String name) {
        return parent.children().stream().filter(c -> c.name().equals(name)).findFirst().orElse(null);
    }
}
