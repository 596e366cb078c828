package org.parpe.core.load;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Names;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.lang.Vocabulary.Element;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import org.parpe.core.xml.InputFiles;
import org.parpe.core.xml.SourceText;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XText;
import org.parpe.core.xml.XmlReader;

/**
 * Reads the main file and its includes (PARSL.md §1, §9) and lists their sections in document
 * order, the content of an include standing where its {@code <include>} is.
 */
final class Includes {
    /** How deep includes may nest: far beyond real use, and the assembly recurses once per level. */
    static final int MAX_INCLUDE_DEPTH = 64;
    private static final List<String> MERGED = List.of("parameters", "controls", "states", "automata", "behaviors");

    /**
     * A section and where it counts as defined.
     *
     * @param element the section element
     * @param order   its place in the merged document order
     * @param anchor  for included content, the {@code <include>} in the main file; else {@code null}
     */
    record Section(XElement element, int order, SourcePos anchor) {
        /** Where a definition in this section is reported when it clashes. */
        SourcePos reportAt(SourcePos own) {
            return anchor == null ? own : anchor;
        }
    }

    /**
     * What reading a main file and its includes gave.
     *
     * @param sections   the merged sections ({@code parameters}, {@code controls}, {@code states},
     *                   {@code automata}, {@code behaviors}) in document order
     * @param files      the main file and every included file read, in the order read
     * @param root       the root element of the main file, or {@code null} if it did not parse
     * @param robot      the main file's {@code <robot>}, or {@code null}
     * @param robotOrder the robot's place in the merged document order
     * @param main       the main file's {@code <main>}, or {@code null}
     */
    record Assembled(List<Section> sections, List<Path> files, XElement root, XElement robot, int robotOrder,
                     XElement main) {
        Assembled {
            sections = List.copyOf(sections);
            files = List.copyOf(files);
        }

        /** The sections of one kind, in document order. */
        List<Section> of(String kind) {
            return sections.stream().filter(s -> s.element().name().equals(kind)).toList();
        }

        /** Whether nothing of a program was found (the main file did not parse). */
        boolean nothing() {
            return robot == null && sections.isEmpty() && main == null;
        }
    }

    private final List<Section> sections = new ArrayList<>();
    private final List<Path> files = new ArrayList<>();
    private XElement robot;
    private int robotOrder;
    private XElement main;
    private XElement root;
    private final DiagnosticSink diags;
    private final Path confinedTo;
    private final Deque<Path> stack = new ArrayDeque<>();
    private final Set<Path> done = new HashSet<>();
    private int order;

    private Includes(DiagnosticSink diags, Path confinedTo) {
        this.diags = diags;
        this.confinedTo = confinedTo;
    }

    /**
     * Reads the main file {@code file}, whose text is given (it may come from an editor), and its
     * includes; with {@code confinedTo} (null: anywhere) only includes inside that folder.
     */
    static Assembled read(Path file, String text, DiagnosticSink diags, Path confinedTo) {
        Includes a = new Includes(diags, confinedTo);
        a.addMain(file, text);
        return new Assembled(a.sections, a.files, a.root, a.robot, a.robotOrder, a.main);
    }

    private void addMain(Path file, String text) {
        files.add(file);
        SourceText src = new SourceText(file.toString(), text);
        if (XmlReader.noElement(text)) {
            // a beginner's new file: say what is missing rather than the parser's "Unexpected EOF in prolog"
            diags.error(src.pos(0), Msg.NO_SCRIPT_YET);
            return;
        }
        XElement root = XmlReader.read(src, diags);
        if (root == null) {
            return;
        }
        Msg other = otherKind(root);
        if (other != null) {
            diags.error(root.pos(), other);
            return;
        }
        this.root = root;
        Attrs.allow(root, diags, Element.PROGRAM.attributes());
        Attrs.noText(root, diags);
        stack.push(key(file));
        done.add(key(file));
        walk(root, file, null, true);
        stack.pop();
    }

    /**
     * What to say of another kind of PARPE file given as a script: the root of a hardware
     * profile, simulator robot configuration or world without a {@code <robot>} section (or an
     * include that could hold one) is not a script, and its own attributes and elements, each an
     * error in a script, would bury that; {@code null} for anything else. A script's root may have
     * any name (PARSL.md §1), so a script called {@code <world>} with its robot stays a script.
     */
    private static Msg otherKind(XElement root) {
        Msg option = switch (root.name()) {
            case "hardware" -> Msg.NOT_A_SCRIPT_HARDWARE;
            case "robot-config" -> Msg.NOT_A_SCRIPT_ROBOT_CONFIG;
            case "world" -> Msg.NOT_A_SCRIPT_WORLD;
            default -> null;
        };
        if (option == null || root.children().stream().anyMatch(c -> c.name().equals("robot") || c.name().equals("include"))) {
            return null;
        }
        return option;
    }

    private static Path key(Path p) {
        return p.toAbsolutePath().normalize();
    }

    private void walk(XElement root, Path file, SourcePos anchor, boolean isMain) {
        Set<String> seen = new HashSet<>();
        for (XElement s : root.children()) {
            String name = s.name();
            if (name.equals(Vocabulary.INCLUDE)) {
                include(s, file, anchor == null ? s.pos() : anchor);
                continue;
            }
            if (!Vocabulary.SECTIONS.contains(name)) {
                String best = Names.closest(name, Vocabulary.SECTIONS);
                diags.error(s.pos(), Msg.UNKNOWN_SECTION, name, best != null ? Message.of(Msg.DID_YOU_MEAN_ELEMENT, best)
                        : Message.of(Msg.SECTIONS_ARE, String.join(", ", Vocabulary.SECTIONS)));
                continue;
            }
            if (!seen.add(name)) {
                diags.error(s.pos(), Msg.SECTION_TWICE, name, s.source().file());
                continue;
            }
            if (name.equals("robot") && isMain) {
                robot = s;
                robotOrder = order++;
            } else if (name.equals("main") && isMain) {
                main = s;
            } else if (MERGED.contains(name)) {
                sections.add(new Section(s, order++, anchor));
            }
        }
    }

    private void include(XElement inc, Path from, SourcePos anchor) {
        Attrs.allow(inc, diags, Element.INCLUDE.attributes());
        Attrs.noChildren(inc, diags);
        Attrs.noText(inc, diags);
        XText rel = Attrs.require(inc, "file", diags);
        if (rel == null) {
            return;
        }
        Path target = resolve(from, rel.value().trim());
        Message outside = outside(target, confinedTo);
        if (outside != null) {
            diags.error(rel.pos(), Msg.CANNOT_INCLUDE, rel.value().trim(), outside);
            return;
        }
        Path k = key(target);
        if (stack.contains(k)) {
            List<String> chain = new ArrayList<>();
            stack.descendingIterator().forEachRemaining(p -> chain.add(p.getFileName().toString()));
            chain.add(target.getFileName().toString());
            diags.error(rel.pos(), Msg.INCLUDE_CYCLE, String.join(" -> ", chain));
            return;
        }
        if (stack.size() > MAX_INCLUDE_DEPTH) {
            diags.error(rel.pos(), Msg.INCLUDE_TOO_DEEP, stack.size(), MAX_INCLUDE_DEPTH);
            return;
        }
        if (!done.add(k)) {
            return; // reached twice without a cycle: loaded once
        }
        String text;
        try {
            files.add(target);
            text = InputFiles.readText(target);
        } catch (IOException e) {
            diags.error(rel.pos(), Msg.CANNOT_READ_INCLUDED, target, e.getMessage());
            return;
        }
        XElement root = XmlReader.read(new SourceText(target.toString(), text), diags);
        if (root == null) {
            return;
        }
        stack.push(k);
        walk(root, target, anchor, false);
        stack.pop();
    }

    /** {@code rel} relative to the folder of {@code from}, as the user would name it. */
    static Path resolve(Path from, String rel) {
        Path parent = from.getParent();
        Path p = parent == null ? Path.of(rel) : parent.resolve(rel);
        return p.normalize();
    }

    /**
     * Why {@code target} may not be read under confinement to {@code root}, a folder or a lone
     * script (null: it may, or there is no confinement): it lies outside, by its name or by a link. Graded
     * scripts are confined to their student's folder (docs/tutorial/teachers.md).
     */
    static Message outside(Path target, Path root) {
        if (root == null) {
            return null;
        }
        Path r = key(root);
        boolean inside = key(target).startsWith(r);
        try {
            if (inside && java.nio.file.Files.exists(target)) {
                inside = target.toRealPath().startsWith(r.toRealPath());
            }
        } catch (IOException | SecurityException e) {
            inside = false;
        }
        if (inside) {
            return null;
        }
        return java.nio.file.Files.isDirectory(root) ? Message.of(Msg.CONFINED_TO_FOLDER, root.getFileName())
                : Message.of(Msg.CONFINED_TO_FILE);
    }
}
