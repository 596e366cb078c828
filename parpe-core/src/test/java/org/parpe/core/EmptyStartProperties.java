package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.Size;
import org.parpe.core.diagram.BehaviorEdits;
import org.parpe.core.diagram.PaletteEdits;
import org.parpe.core.edit.SectionEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;

/**
 * Issue 24, item 5: a script is built from an empty file by the palette's edits alone. The
 * property starts from an empty text (nothing, white space, a declaration, comments), starts a
 * robot and makes random palette edits; after each, the text is exactly the one a person writes
 * by hand in the examples' layout (the sections in {@link SectionEdits#ORDER}, two spaces per
 * level), rendered here from lists of lines without the parser or any span, and it loads.
 */
class EmptyStartProperties {
    private static final Path FILE = Path.of("built.xml");
    private static final List<String> EMPTY = List.of("", "\n", "  \n\t ", "<?xml version=\"1.0\"?>",
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- my robot -->\n", "<!-- a -->\n\n<!-- b -->  \n");

    @Example
    void anEmptyFileIsOneWithoutElements() {
        for (String e : EMPTY) {
            assertTrue(SectionEdits.blank(e), e);
        }
        assertTrue(SectionEdits.blank("\uFEFF<?xml version=\"1.0\"?>"));
        assertFalse(SectionEdits.blank("<program/>"));
        assertFalse(SectionEdits.blank("<!-- not closed"));
        assertFalse(SectionEdits.blank("<?xml version=\"1.0\"?>\nhello"));
    }

    /** Before: "malformed XML: Unexpected EOF in prolog" at the file's end, a parser's words for a beginner's first file. */
    @Example
    void anEmptyFileIsReportedAsEmptyNotAsMalformed() {
        for (String e : EMPTY) {
            LoadResult r = ScriptLoader.loadText(FILE, e, Map.of());
            assertEquals(List.of("built.xml:1:1: error: the file holds no script yet: a script is one element,"
                    + " conventionally <program>, with at least a <robot> section (PARSL.md §1)"),
                    r.diagnostics().stream().map(d -> d.format()).toList(), e);
        }
    }

    @Example
    void theRobotStartsAfterTheDeclarationAndComment() {
        String text = "<?xml version=\"1.0\"?>\n<!-- my robot -->\n\n";
        String started = SectionEdits.startRobot(text, "body", 8).apply(text);
        assertEquals("<?xml version=\"1.0\"?>\n<!-- my robot -->\n<program>\n  <robot>\n    <structure>\n"
                + "      <body elements=\"0..7\"/>\n    </structure>\n  </robot>\n</program>\n", started);
        LoadResult r = ScriptLoader.loadText(FILE, started, Map.of());
        assertTrue(r.ok() && r.errors().isEmpty(), r.diagnostics().toString());
        assertEquals(8, r.program().moduleIds().length);
        assertEquals("<program>\n  <robot>\n    <structure>\n      <one elements=\"0\"/>\n    </structure>\n  </robot>\n"
                + "</program>\n", SectionEdits.startRobot("", "one", 1).apply(""));
        assertEquals("the file has a script already; a robot is started only in an empty file", assertThrows(
                IllegalArgumentException.class, () -> SectionEdits.startRobot(started, "b", 2)).getMessage());
        assertEquals("a robot has 1 to 10000 modules, not 0", assertThrows(IllegalArgumentException.class,
                () -> SectionEdits.startRobot("", "b", 0)).getMessage());
    }

    /** Issue 31: the palette starts a gait table as rows × modules of 0 (it was typed as "0,0,…; 0,0,…"). */
    @Example
    void aGaitTableStartsAsRowsTimesModulesOfZeros() {
        String text = SectionEdits.startRobot("", "body", 3).apply("");
        Program p = ScriptLoader.loadText(FILE, text, Map.of()).program();
        assertEquals("<program>\n  <robot>\n    <structure>\n      <body elements=\"0..2\"/>\n    </structure>\n  </robot>\n"
                + "  <automata>\n    <wave>\n      0, 0, 0\n      0, 0, 0\n    </wave>\n  </automata>\n</program>\n",
                PaletteEdits.addGaitTable(text, p, "wave", "2", " 3 ", "").apply(text));
        assertEquals("rows must be a whole number from 1 to 1000, got 'two'", assertThrows(IllegalArgumentException.class,
                () -> PaletteEdits.addGaitTable(text, p, "wave", "two", "3", "")).getMessage());
        assertEquals("modules must be from 1 to 1000, got 0", assertThrows(IllegalArgumentException.class,
                () -> PaletteEdits.addGaitTable(text, p, "wave", "2", "0", "")).getMessage());
    }

    /** Labels count as people do (issue 31: "entry 0", "#0"). */
    @Example
    void placesAreWordsFromFirst() {
        assertEquals(List.of("first", "second", "third", "tenth", "11th", "12th", "13th", "21st", "22nd", "23rd", "111th"),
                java.util.stream.IntStream.of(0, 1, 2, 9, 10, 11, 12, 20, 21, 22, 110)
                        .mapToObj(org.parpe.core.lang.Numbers::ordinal).toList());
    }

    @Example
    void aMissingSectionGoesWhereTheExamplesHaveIt() throws Exception {
        Path f = Examples.dir().resolve("hello-snake.xml");
        String text = Files.readString(f);
        Program p = ScriptLoader.load(f, Map.of()).program();
        String edited = PaletteEdits.addParameter(text, p, "amp", "30", "0", "90", "Amplitude").apply(text);
        assertEquals(text.replace("  </robot>\n", "  </robot>\n  <parameters>\n"
                + "    <amp value=\"30\" min=\"0\" max=\"90\" label=\"Amplitude\"/>\n  </parameters>\n"), edited);
        assertTrue(ScriptLoader.loadText(f, edited, Map.of()).ok());
        String robotFile = "<program><robot file=\"r.xml\"/></program>";
        Program q = ScriptLoader.loadText(FILE, "<program><robot><structure><b elements=\"0\"/></structure></robot></program>",
                Map.of()).program();
        assertEquals("<robot> is read from r.xml; add to it there", assertThrows(IllegalArgumentException.class,
                () -> PaletteEdits.addGroup(robotFile, q, "c", "1")).getMessage());
    }

    /** The script as a person writes it: each section's lines, in the examples' order. */
    private static final class ByHand {
        final String prefix;
        final Map<String, List<String>> sections = new LinkedHashMap<>();
        final Map<String, List<String>> behaviors = new LinkedHashMap<>();

        ByHand(String empty) {
            String kept = empty.stripTrailing();
            prefix = kept.isEmpty() ? "" : kept + "\n";
            for (String s : SectionEdits.ORDER) {
                sections.put(s, new ArrayList<>());
            }
        }

        String text() {
            StringBuilder out = new StringBuilder(prefix).append("<program>\n  <robot>\n    <structure>\n");
            sections.get("robot").forEach(l -> out.append("      ").append(l).append('\n'));
            out.append("    </structure>\n  </robot>\n");
            for (String s : SectionEdits.ORDER.subList(1, SectionEdits.ORDER.size())) {
                List<String> lines = new ArrayList<>(sections.get(s));
                if (s.equals("behaviors")) {
                    behaviors.forEach((b, items) -> {
                        lines.add("<" + b + ">");
                        items.forEach(i -> lines.add("  " + i));
                        lines.add("</" + b + ">");
                    });
                }
                if (!lines.isEmpty()) {
                    out.append("  <").append(s).append(">\n");
                    lines.forEach(l -> out.append("    ").append(l).append('\n'));
                    out.append("  </").append(s).append(">\n");
                }
            }
            return out.append("</program>\n").toString();
        }
    }

    @Property(tries = 200)
    void aScriptBuiltFromAnEmptyFileIsTheOneWrittenByHand(@ForAll @IntRange(min = 0, max = 5) int empty,
                                                          @ForAll @IntRange(min = 1, max = 20) int modules,
                                                          @ForAll @Size(max = 25) List<@IntRange(min = 0, max = 6) Integer> steps) {
        String text = EMPTY.get(empty);
        ByHand hand = new ByHand(text);
        text = SectionEdits.startRobot(text, "body", modules).apply(text);
        hand.sections.get("robot").add("<body elements=\"" + (modules == 1 ? "0" : "0.." + (modules - 1)) + "\"/>");
        assertEquals(hand.text(), text);
        List<String> groups = new ArrayList<>(List.of("body"));
        List<String> poses = new ArrayList<>();
        List<String> automata = new ArrayList<>();
        Map<String, List<String>> groupsOf = new LinkedHashMap<>();
        for (int k = 0; k < steps.size(); k++) {
            Program p = loaded(text);
            String n = Integer.toString(k);
            TextEdit edit = null;
            switch (steps.get(k)) {
                case 0 -> {
                    // disjoint from the chain and from each other: a behavior drives each module once
                    String elements = (100 + 10 * k) + ".." + (102 + 10 * k);
                    edit = PaletteEdits.addGroup(text, p, "g" + n, elements);
                    hand.sections.get("robot").add("<g" + n + " elements=\"" + elements + "\"/>");
                    groups.add("g" + n);
                }
                case 1 -> {
                    boolean bounded = k % 2 == 0;
                    edit = PaletteEdits.addParameter(text, p, "p" + n, n, bounded ? "0" : "", bounded ? "99" : " ",
                            bounded ? "P & " + n : "");
                    hand.sections.get("parameters").add("<p" + n + " value=\"" + n + "\"" + (bounded ? " min=\"0\" max=\"99\" label=\"P &amp; "
                            + n + "\"" : "") + "/>");
                }
                case 2 -> {
                    edit = PaletteEdits.addPose(text, p, "s" + n, "-" + n);
                    hand.sections.get("states").add("<s" + n + " angles=\"-" + n + "\"/>");
                    poses.add("s" + n);
                }
                case 3 -> {
                    if (poses.isEmpty()) {
                        continue;
                    }
                    String states = poses.get(k % poses.size()) + ", " + poses.get(0);
                    String times = k % 3 == 0 ? "" : "0.5, " + n;
                    edit = PaletteEdits.addAutomaton(text, p, "a" + n, states, times);
                    hand.sections.get("automata").add("<a" + n + " states=\"" + states + "\"" + (times.isEmpty() ? ""
                            : " times=\"" + times + "\"") + "/>");
                    automata.add("a" + n);
                }
                case 4 -> {
                    edit = PaletteEdits.addGaitTable(text, p, "t" + n, List.of(n, "-" + n), "1, 2");
                    List<String> lines = hand.sections.get("automata");
                    lines.add("<t" + n + " times=\"1, 2\">");
                    lines.add("  " + n);
                    lines.add("  -" + n);
                    lines.add("</t" + n + ">");
                    automata.add("t" + n);
                }
                case 5 -> {
                    if (automata.isEmpty()) {
                        continue;
                    }
                    String a = automata.get(k % automata.size());
                    String g = groups.get(k % groups.size());
                    String time = k % 2 == 0 ? "" : n;
                    edit = BehaviorEdits.addBehavior(text, p, "b" + n, a, g, time);
                    hand.sections.get("main").add("<b" + n + (time.isEmpty() ? "" : " time=\"" + time + "\"") + "/>");
                    hand.behaviors.put("b" + n, new ArrayList<>(List.of("<" + a + " group=\"" + g + "\"/>")));
                    groupsOf.put("b" + n, new ArrayList<>(List.of(g)));
                }
                default -> {
                    if (groupsOf.isEmpty()) {
                        continue;
                    }
                    String b = new ArrayList<>(groupsOf.keySet()).get(k % groupsOf.size());
                    String g = groups.stream().filter(x -> !groupsOf.get(b).contains(x)).findFirst().orElse(null);
                    if (g == null) {
                        continue;
                    }
                    String a = automata.get(k % automata.size());
                    edit = BehaviorEdits.addInstance(text, p.behavior(b).orElseThrow(), a, g);
                    hand.behaviors.get(b).add("<" + a + " group=\"" + g + "\"/>");
                    groupsOf.get(b).add(g);
                }
            }
            text = edit.apply(text);
            assertEquals(hand.text(), text, "step " + k + " (" + steps.get(k) + ")");
        }
        loaded(text);
    }

    private static Program loaded(String text) {
        LoadResult r = ScriptLoader.loadText(FILE, text, Map.of());
        assertTrue(r.ok() && r.errors().isEmpty(), () -> r.diagnostics() + "\n" + text);
        return r.program();
    }
}
