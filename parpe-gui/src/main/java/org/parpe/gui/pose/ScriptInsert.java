package org.parpe.gui.pose;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.edit.ElementWriter;
import org.parpe.core.edit.Replacement;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Group;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;
import org.parpe.gui.text.PanelMsg;
import org.parpe.serial.record.PoseRecording;
import org.parpe.core.xml.SourceText;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XmlReader;
import org.parpe.serial.record.RecordingWriter;

/**
 * "Use on another group": writes a recording into a script as a gait-table automaton (one row per
 * pose, PARSL.md §12) and a behavior that plays it on the chosen groups with a period, a phase and
 * an offset, group {@code k} (from 0) lagging by {@code k × offset} cycles; adds a {@code <main>}
 * entry when the script has no {@code <main>} or an empty one. Names that the script already uses
 * get a number. Pure text in, text out; the sections are found by their source spans (so a
 * section's name in a comment is not taken for it) and the elements written by the edit layer.
 */
final class ScriptInsert {
    /** How many cycles a behavior put first in a {@code <main>} that had entries plays before them. */
    static final int FIRST_CYCLES = 3;

    /**
     * What to write; {@code playFirst}: when {@code <main>} has entries, put the new behavior first
     * in it for {@value #FIRST_CYCLES} cycles (then the entries it had play); otherwise leave
     * {@code <main>} as it is (the behavior does not play until it is added there).
     */
    record Request(PoseRecording recording, List<String> targets, double period, double phase, double offset, boolean playFirst) {
        Request(PoseRecording recording, List<String> targets, double period, double phase, double offset) {
            this(recording, targets, period, phase, offset, true);
        }
    }

    /** What became of {@code <main>}. */
    enum Main {
        /** {@code <main>} had no entries: now it plays the new behavior alone. */
        ONLY,
        /** The new behavior plays first, for {@link #FIRST_CYCLES} cycles, then the entries {@code <main>} had. */
        FIRST,
        /** {@code <main>} is unchanged: the new behavior does not play. */
        UNCHANGED
    }

    /** The new text, the names given to the automaton and the behavior, and what became of {@code <main>}. */
    record Result(String text, String automaton, String behavior, Main main, double firstSeconds) {
        boolean mainAdded() {
            return main != Main.UNCHANGED;
        }

        /** One sentence for the user: what was written and whether (and when) the script plays it. */
        String said(List<String> targets) {
            String on = String.join(", ", targets);
            return switch (main) {
                case ONLY -> PanelMsg.POSE_ADDED_ONLY.text(automaton, behavior, on);
                case FIRST -> PanelMsg.POSE_ADDED_FIRST.text(automaton, behavior, on, number(firstSeconds));
                case UNCHANGED -> PanelMsg.POSE_ADDED_UNCHANGED.text(automaton, behavior, on);
            };
        }
    }

    private ScriptInsert() {
    }

    /**
     * Checks the request against {@code program}: returns a message for the user, or null if it
     * can be written.
     */
    static String check(Program program, Request r) {
        if (r.targets().isEmpty()) {
            return PanelMsg.POSE_CHOOSE_TARGET.text();
        }
        if (!(r.period() > 0) || Double.isInfinite(r.period())) {
            return PanelMsg.POSE_PERIOD_POSITIVE.text(r.period());
        }
        if (!Double.isFinite(r.phase()) || !Double.isFinite(r.offset())) {
            return PanelMsg.POSE_PHASE_OFFSET_NUMBERS.text();
        }
        Set<Integer> used = new HashSet<>();
        for (String t : r.targets()) {
            Group g = program.group(t).orElse(null);
            if (g == null) {
                return PanelMsg.POSE_NO_GROUP.text(t);
            }
            if (g.size() != r.recording().modules().length) {
                return PanelMsg.POSE_GROUP_SIZE.text(t, g.size(), r.recording().modules().length);
            }
            for (int id : g.modules()) {
                if (!used.add(id)) {
                    return PanelMsg.POSE_GROUPS_SHARE.text(r.targets(), id);
                }
            }
        }
        return null;
    }

    /** Writes the request into {@code text}, whose loaded program is {@code program}. */
    static Result insert(String text, Program program, Request r) {
        Set<String> taken = names(program);
        String auto = unique("rec_" + r.recording().group(), taken);
        taken.add(auto);
        String beh = unique("play_" + r.recording().group(), taken);
        XElement root = XmlReader.read(new SourceText(program.file(), text), new DiagnosticList());
        if (root == null) {
            throw new IllegalArgumentException(PanelMsg.POSE_NOT_WELL_FORMED.text());
        }
        List<Replacement> edits = new ArrayList<>();
        edits.add(section(text, root, "automata", automaton(auto, r.recording())));
        edits.add(section(text, root, "behaviors", behavior(beh, auto, r)));
        boolean emptyMain = program.mainDef().map(m -> m.entries().isEmpty()).orElse(true);
        Main main = emptyMain ? Main.ONLY : r.playFirst() ? Main.FIRST : Main.UNCHANGED;
        double first = FIRST_CYCLES * r.period();
        if (main == Main.ONLY) {
            edits.add(section(text, root, "main", ElementWriter.tag(beh).empty() + "\n"));
        } else if (main == Main.FIRST) {
            XElement m = child(root, "main", false);
            edits.addAll(ScriptEdits.prependChild(text, m.span(),
                    ElementWriter.tag(beh).attr("time", number(first)).empty()).replacements());
        }
        // a later insertion at the same place goes before an earlier one, as the sections were always written
        Collections.reverse(edits);
        return new Result(new TextEdit(edits).apply(text), auto, beh, main, main == Main.FIRST ? first : 0);
    }

    /**
     * Adds {@code body} (lines, unindented) at the end of section {@code name} (a child of the
     * root, found by its span), creating it at the end of the root if needed.
     */
    private static Replacement section(String text, XElement root, String name, String body) {
        XElement open = child(root, name, false);
        if (open != null) {
            int at = text.lastIndexOf("</", open.span().end() - 1);
            String indent = indentAt(text, at);
            int lineStart = text.lastIndexOf('\n', at - 1) + 1;
            String block = ElementWriter.indentLines(body, indent + "  ");
            return text.substring(lineStart, at).isBlank() ? new Replacement(lineStart, 0, block)
                    : new Replacement(at, 0, "\n" + block + indent);
        }
        XElement empty = child(root, name, true);
        if (empty != null) {
            SourceSpan s = empty.span();
            String indent = indentAt(text, s.start());
            String attrs = text.substring(s.start() + 1 + name.length(), s.tagEnd()).stripTrailing();
            return new Replacement(s.start(), s.end() - s.start(), "<" + name + attrs + ">\n"
                    + ElementWriter.indentLines(body, indent + "  ") + indent + ElementWriter.close(name));
        }
        int end = root.span().empty() ? text.length() : text.lastIndexOf("</", root.span().end() - 1);
        int lineStart = text.lastIndexOf('\n', end - 1) + 1;
        String block = "  " + ElementWriter.tag(name).open() + "\n" + ElementWriter.indentLines(body, "    ") + "  "
                + ElementWriter.close(name) + "\n";
        return text.substring(lineStart, end).isBlank() ? new Replacement(lineStart, 0, block)
                : new Replacement(end, 0, "\n" + block);
    }

    /**
     * The last child of {@code root} named {@code name} written with an end tag, or
     * ({@code empty}) the first written as {@code <name/>}; null when there is none.
     */
    private static XElement child(XElement root, String name, boolean empty) {
        XElement found = null;
        for (XElement c : root.children()) {
            if (c.name().equals(name) && c.span().empty() == empty && (found == null || !empty)) {
                found = c;
            }
        }
        return found;
    }

    private static String automaton(String name, PoseRecording rec) {
        double[] t = RecordingWriter.rowTimes(rec);
        StringBuilder times = new StringBuilder();
        StringBuilder rows = new StringBuilder();
        for (int i = 0; i < rec.size(); i++) {
            times.append(i == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.2f", t[i]));
            double[] p = rec.pose(i);
            rows.append("  ");
            for (int k = 0; k < p.length; k++) {
                rows.append(k == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.2f", p[k] == 0 ? 0.0 : p[k]));
            }
            rows.append('\n');
        }
        return "<!-- " + rec.size() + " poses of group " + rec.group() + ", recorded in the Pose panel -->\n"
                + ElementWriter.tag(name).attr("times", times.toString()).open() + "\n" + rows + ElementWriter.close(name) + "\n";
    }

    private static String behavior(String name, String auto, Request r) {
        StringBuilder b = new StringBuilder(ElementWriter.tag(name).open()).append('\n');
        for (int k = 0; k < r.targets().size(); k++) {
            b.append("  ").append(ElementWriter.tag(auto).attr("group", r.targets().get(k)).attr("period", number(r.period()))
                    .attr("phase", number(r.phase())).attr("offset", number(k * r.offset())).empty()).append('\n');
        }
        return b.append(ElementWriter.close(name)).append('\n').toString();
    }

    private static String number(double v) {
        String s = String.format(Locale.ROOT, "%.4f", v == 0 ? 0.0 : v).replaceFirst("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }

    private static String indentAt(String text, int at) {
        int lineStart = text.lastIndexOf('\n', at - 1) + 1;
        int i = lineStart;
        while (i < at && (text.charAt(i) == ' ' || text.charAt(i) == '\t')) {
            i++;
        }
        return text.substring(lineStart, i);
    }

    /** Every name the program defines, and the reserved words are never free either. */
    private static Set<String> names(Program p) {
        Set<String> n = new HashSet<>();
        p.robot().groups().forEach(g -> n.add(g.name()));
        p.parameters().forEach(x -> n.add(x.name()));
        p.controls().forEach(x -> n.add(x.name()));
        p.radioWords().keySet().forEach(n::add);
        p.states().stream().map(StateDef::name).forEach(n::add);
        p.automata().stream().map(Automaton::name).forEach(n::add);
        for (Behavior b : p.behaviors()) {
            n.add(b.name());
            n.addAll(b.macros());
        }
        return n;
    }

    private static String unique(String base, Set<String> taken) {
        String name = base;
        for (int k = 2; taken.contains(name) || Vocabulary.isReserved(name); k++) {
            name = base + "_" + k;
        }
        return name;
    }
}
