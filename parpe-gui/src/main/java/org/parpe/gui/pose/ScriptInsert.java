package org.parpe.gui.pose;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Group;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;
import org.parpe.serial.record.PoseRecording;
import org.parpe.serial.record.RecordingWriter;

/**
 * "Use on another group": writes a recording into a script as a gait-table automaton (one row per
 * pose, PARSL.md §12) and a behavior that plays it on the chosen groups with a period, a phase and
 * an offset, group {@code k} (from 0) lagging by {@code k × offset} cycles; adds a {@code <main>}
 * entry when the script has no {@code <main>} or an empty one. Names that the script already uses
 * get a number. Pure text in, text out; comments are left alone.
 */
final class ScriptInsert {
    private static final Pattern ROOT_END = Pattern.compile("</\\s*[A-Za-z_][\\w.-]*\\s*>\\s*$");

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
            String head = "Added automaton " + automaton + " and behavior " + behavior + " playing it on " + String.join(", ", targets);
            return head + switch (main) {
                case ONLY -> "; <main> plays it.";
                case FIRST -> "; <main> now plays it first, for " + number(firstSeconds) + " s, then the entries it had.";
                case UNCHANGED -> ". It is not in <main>, so the script does not play it yet: add <" + behavior + "/> to <main>.";
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
            return "Choose at least one group to play the poses on.";
        }
        if (!(r.period() > 0) || Double.isInfinite(r.period())) {
            return "The period must be a number of seconds > 0, got " + r.period() + ".";
        }
        if (!Double.isFinite(r.phase()) || !Double.isFinite(r.offset())) {
            return "Phase and offset must be numbers of cycles.";
        }
        Set<Integer> used = new HashSet<>();
        for (String t : r.targets()) {
            Group g = program.group(t).orElse(null);
            if (g == null) {
                return "The script has no group '" + t + "'.";
            }
            if (g.size() != r.recording().modules().length) {
                return "Group '" + t + "' has " + g.size() + " modules but the poses have " + r.recording().modules().length
                        + " angles.";
            }
            for (int id : g.modules()) {
                if (!used.add(id)) {
                    return "Groups " + r.targets() + " share module " + id
                            + "; automata in one behavior must drive different modules.";
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
        String masked = maskComments(text);
        List<Edit> edits = new ArrayList<>();
        section(masked, "automata", automaton(auto, r.recording()), edits);
        section(masked, "behaviors", behavior(beh, auto, r), edits);
        boolean emptyMain = program.mainDef().map(m -> m.entries().isEmpty()).orElse(true);
        Main main = emptyMain ? Main.ONLY : r.playFirst() ? Main.FIRST : Main.UNCHANGED;
        double first = FIRST_CYCLES * r.period();
        if (main == Main.ONLY) {
            section(masked, "main", "<" + beh + "/>\n", edits);
        } else if (main == Main.FIRST) {
            first(masked, "<" + beh + " time=\"" + number(first) + "\"/>", edits);
        }
        edits.sort((a, b) -> Integer.compare(b.at, a.at));
        StringBuilder out = new StringBuilder(text);
        for (Edit e : edits) {
            out.replace(e.at, e.at + e.length, e.text);
        }
        return new Result(out.toString(), auto, beh, main, main == Main.FIRST ? first : 0);
    }

    /** Puts {@code entry} first in the (non-empty) {@code <main>}, on its own line. */
    private static void first(String masked, String entry, List<Edit> edits) {
        Matcher open = Pattern.compile("<\\s*main(\\s[^>]*)?(?<!/)>").matcher(masked);
        if (open.find()) {
            edits.add(new Edit(open.end(), 0, "\n" + indentAt(masked, open.start()) + "  " + entry));
        }
    }

    private record Edit(int at, int length, String text) {
    }

    /** Adds {@code body} (lines, unindented) at the end of section {@code name}, creating it if needed. */
    private static void section(String masked, String name, String body, List<Edit> edits) {
        Matcher close = Pattern.compile("</\\s*" + name + "\\s*>").matcher(masked);
        int at = -1;
        while (close.find()) {
            at = close.start();
        }
        if (at >= 0) {
            String indent = indentAt(masked, at);
            int lineStart = masked.lastIndexOf('\n', at - 1) + 1;
            boolean ownLine = masked.substring(lineStart, at).isBlank();
            String block = indent(body, indent + "  ");
            edits.add(ownLine ? new Edit(lineStart, 0, block) : new Edit(at, 0, "\n" + block + indent));
            return;
        }
        Matcher empty = Pattern.compile("<\\s*" + name + "(\\s[^>]*)?/>").matcher(masked);
        if (empty.find()) {
            String indent = indentAt(masked, empty.start());
            String attrs = empty.group(1) == null ? "" : empty.group(1).stripTrailing();
            edits.add(new Edit(empty.start(), empty.end() - empty.start(),
                    "<" + name + attrs + ">\n" + indent(body, indent + "  ") + indent + "</" + name + ">"));
            return;
        }
        Matcher root = ROOT_END.matcher(masked);
        int end = root.find() ? root.start() : masked.length();
        int lineStart = masked.lastIndexOf('\n', end - 1) + 1;
        boolean ownLine = masked.substring(lineStart, end).isBlank();
        String block = "  <" + name + ">\n" + indent(body, "    ") + "  </" + name + ">\n";
        edits.add(ownLine ? new Edit(lineStart, 0, block) : new Edit(end, 0, "\n" + block));
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
                + "<" + name + " times=\"" + times + "\">\n" + rows + "</" + name + ">\n";
    }

    private static String behavior(String name, String auto, Request r) {
        StringBuilder b = new StringBuilder("<" + name + ">\n");
        for (int k = 0; k < r.targets().size(); k++) {
            b.append(String.format(Locale.ROOT, "  <%s group=\"%s\" period=\"%s\" phase=\"%s\" offset=\"%s\"/>%n", auto,
                    r.targets().get(k), number(r.period()), number(r.phase()), number(k * r.offset())));
        }
        return b.append("</").append(name).append(">\n").toString().replace(System.lineSeparator(), "\n");
    }

    private static String number(double v) {
        String s = String.format(Locale.ROOT, "%.4f", v == 0 ? 0.0 : v).replaceFirst("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }

    private static String indent(String body, String indent) {
        StringBuilder b = new StringBuilder();
        for (String line : body.split("\n")) {
            b.append(indent).append(line).append('\n');
        }
        return b.toString();
    }

    private static String indentAt(String text, int at) {
        int lineStart = text.lastIndexOf('\n', at - 1) + 1;
        int i = lineStart;
        while (i < at && (text.charAt(i) == ' ' || text.charAt(i) == '\t')) {
            i++;
        }
        return text.substring(lineStart, i);
    }

    /** The text with every comment's characters (but not its line breaks) replaced by spaces. */
    static String maskComments(String text) {
        StringBuilder b = new StringBuilder(text);
        int from = 0;
        while (true) {
            int s = text.indexOf("<!--", from);
            if (s < 0) {
                break;
            }
            int e = text.indexOf("-->", s + 4);
            e = e < 0 ? text.length() : e + 3;
            for (int i = s; i < e; i++) {
                if (b.charAt(i) != '\n') {
                    b.setCharAt(i, ' ');
                }
            }
            from = e;
        }
        return b.toString();
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
