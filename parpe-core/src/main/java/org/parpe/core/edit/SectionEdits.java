package org.parpe.core.edit;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.text.EditMsg;
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
            throw new EditRefused(EditMsg.NOT_EMPTY);
        }
        ElementWriter.name(group, "group");
        if (modules < 1 || modules > MAX_MODULES) {
            throw new EditRefused(EditMsg.MODULE_COUNT, MAX_MODULES, modules);
        }
        int end = text.length();
        while (end > 0 && Character.isWhitespace(text.charAt(end - 1))) {
            end--;
        }
        String elements = modules == 1 ? "0" : "0.." + (modules - 1);
        String robot = ElementWriter.tag("robot").lines("  ", List.of(ElementWriter.tag("structure").lines("    ",
                List.of(ElementWriter.tag(group).attr("elements", elements).empty()))));
        String program = ElementWriter.tag(Vocabulary.ROOT).lines("", List.of(robot)) + "\n";
        return TextEdit.of(end, text.length() - end, (end == 0 ? "" : "\n") + program);
    }

    /**
     * Puts a new element as the last child of the element at {@code path} below the root (a
     * section, or {@code "robot", "structure"}), writing whichever of them the file lacks.
     * {@code element} gives the element's text for the indentation of its first line (its
     * further lines carry that indentation themselves).
     */
    public static TextEdit add(String text, String file, Function<String, String> element, String... path) {
        DiagnosticList diags = new DiagnosticList();
        XElement parent = XmlReader.read(new SourceText(file, text), diags);
        if (parent == null) {
            throw new EditRefused(EditMsg.NOT_WELL_FORMED);
        }
        for (int level = 0; level < path.length; level++) {
            XElement child = child(parent, path[level]);
            if (child == null) {
                return write(text, parent, level, element, path);
            }
            if (child.attr("file") != null) {
                throw new EditRefused(EditMsg.SECTION_INCLUDED, path[level], child.attr("file").value().value());
            }
            parent = child;
        }
        List<XElement> kids = parent.children();
        SourceSpan ps = parent.span();
        if (!kids.isEmpty()) {
            SourceSpan last = kids.get(kids.size() - 1).span();
            return TextEdit.of(last.end(), 0, "\n" + ElementWriter.indent(text, last.start())
                    + element.apply(ElementWriter.indent(text, last.start())));
        }
        String inner = ElementWriter.indent(text, ps.start()) + "  ";
        return ScriptEdits.appendChild(text, ps, parent.name(), null, element.apply(inner));
    }

    /**
     * Writes the elements {@code path[level..]} that {@code parent} lacks, holding the new element:
     * a new section after the section it follows in {@link #ORDER} (or before the first one),
     * indented as that one; a new element of a section as the section's last child.
     */
    private static TextEdit write(String text, XElement parent, int level, Function<String, String> element,
                                  String... path) {
        return place(text, parent, level == 0 ? ORDER.indexOf(path[0]) : -1, level > 0, indent -> {
            StringBuilder open = new StringBuilder();
            StringBuilder close = new StringBuilder();
            String at = indent;
            for (int k = level; k < path.length; k++) {
                open.append(k == level ? "" : "\n" + at).append(ElementWriter.tag(path[k]).open());
                close.insert(0, "\n" + at + ElementWriter.close(path[k]));
                at += "  ";
            }
            return open + "\n" + at + element.apply(at) + close;
        });
    }

    /**
     * Puts {@code nested} (its text for the indentation it starts at) into {@code parent}: after
     * its last child ({@code afterLast}), or after its last child that comes before {@code rank}
     * in {@link #ORDER}, else before its first child, indented as that one; else as its only child.
     */
    private static TextEdit place(String text, XElement parent, int rank, boolean afterLast, Function<String, String> nested) {
        List<XElement> kids = parent.children();
        XElement before = null;
        if (afterLast) {
            before = kids.isEmpty() ? null : kids.get(kids.size() - 1);
        } else {
            for (XElement k : kids) {
                int r = ORDER.indexOf(k.name());
                if (r >= 0 && r < rank) {
                    before = k;
                }
            }
        }
        XElement like = before != null ? before : kids.isEmpty() ? null : kids.get(0);
        String indent = like == null ? ElementWriter.indent(text, parent.span().start()) + "  "
                : ElementWriter.indent(text, like.span().start());
        if (before != null) {
            return TextEdit.of(before.span().end(), 0, "\n" + indent + nested.apply(indent));
        }
        if (like != null) {
            return TextEdit.of(like.span().start(), 0, nested.apply(indent) + "\n" + indent);
        }
        return ScriptEdits.appendChild(text, parent.span(), parent.name(), null, nested.apply(indent));
    }

    /**
     * Puts a snippet made of sections (a lesson's {@code <states>…</states>}, or several
     * sections) where each belongs, never inside another element: the content of a section the
     * script has goes after that section's last child; a section it lacks is written at the top
     * level, after the section it follows in {@link #ORDER}; a blank file gets a
     * {@code <program>} holding them. Returns null when the snippet is not sections only (an
     * element of a section, whose place depends on what it is for).
     *
     * @throws IllegalArgumentException when the script is not well-formed, or a section is read from another file
     */
    public static TextEdit placeSections(String text, String file, String snippet) {
        String wrapped = ElementWriter.tag(Vocabulary.ROOT).open() + "\n" + snippet + "\n"
                + ElementWriter.close(Vocabulary.ROOT);
        XElement root = XmlReader.read(new SourceText("snippet", wrapped), new DiagnosticList());
        List<XElement> sections = root == null ? List.of() : root.children();
        if (sections.size() == 1 && sections.get(0).name().equals(Vocabulary.ROOT)) {
            sections = sections.get(0).children();
        }
        if (sections.isEmpty() || !sections.stream().allMatch(s -> ORDER.contains(s.name()))) {
            return null;
        }
        if (blank(text)) {
            StringBuilder program = new StringBuilder(ElementWriter.tag(Vocabulary.ROOT).open() + "\n");
            sections.stream().sorted(java.util.Comparator.comparingInt(s -> ORDER.indexOf(s.name())))
                    .forEach(s -> program.append("  ").append(reindent(wrapped, s.span().start(), s.span().end(), "  ")).append('\n'));
            int end = text.length();
            while (end > 0 && Character.isWhitespace(text.charAt(end - 1))) {
                end--;
            }
            return TextEdit.of(end, text.length() - end, (end == 0 ? "" : "\n") + program
                    + ElementWriter.close(Vocabulary.ROOT) + "\n");
        }
        XElement program = XmlReader.read(new SourceText(file, text), new DiagnosticList());
        if (program == null) {
            throw new EditRefused(EditMsg.NOT_WELL_FORMED);
        }
        List<Replacement> out = new ArrayList<>();
        for (XElement s : sections) {
            XElement have = child(program, s.name());
            if (have == null) {
                out.addAll(place(text, program, ORDER.indexOf(s.name()), false,
                        at -> reindent(wrapped, s.span().start(), s.span().end(), at)).replacements());
            } else if (!s.children().isEmpty()) {
                int from = s.children().get(0).span().start();
                int to = s.children().get(s.children().size() - 1).span().end();
                out.addAll(add(text, file, at -> reindent(wrapped, from, to, at), s.name()).replacements());
            }
        }
        return new TextEdit(out);
    }

    /** {@code src[from, to)} with its further lines moved from the first one's indentation to {@code indent}. */
    private static String reindent(String src, int from, int to, String indent) {
        int column = from - (src.lastIndexOf('\n', from - 1) + 1);
        String[] lines = src.substring(from, to).split("\n", -1);
        StringBuilder out = new StringBuilder(lines[0]);
        for (int i = 1; i < lines.length; i++) {
            String line = lines[i];
            int strip = 0;
            while (strip < column && strip < line.length() && line.charAt(strip) == ' ') {
                strip++;
            }
            out.append('\n').append(line.isBlank() ? "" : indent + line.substring(strip));
        }
        return out.toString();
    }

    /**
     * The span of the section {@code name} (a child of the root) that holds {@code offset}, or
     * null when there is none (or the text is not well-formed).
     */
    public static SourceSpan sectionAt(String text, String file, String name, int offset) {
        XElement root = XmlReader.read(new SourceText(file, text), new DiagnosticList());
        for (XElement s : root == null ? List.<XElement>of() : root.children()) {
            if (s.name().equals(name) && s.span().start() <= offset && offset < s.span().end()) {
                return s.span();
            }
        }
        return null;
    }

    private static XElement child(XElement parent, String name) {
        return parent.children().stream().filter(c -> c.name().equals(name)).findFirst().orElse(null);
    }
}
