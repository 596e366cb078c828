package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diagram.BehaviorEdits;
import org.parpe.core.diagram.DiagramEdits;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.diagram.Diagrams;
import org.parpe.core.diagram.PaletteEdits;
import org.parpe.core.diagram.RingEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Parameter;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;

/**
 * Issue 24's acceptance property, over every example and conformance program that loads:
 * building every diagram changes no byte, and a random diagram edit gives exactly the text of
 * the same edit made by hand ({@link HandEdits}, which finds elements by line and column and
 * attributes by regular expressions, not through the spans).
 */
class DiagramEditProperties {
    private static final List<Path> SCRIPTS = scripts();

    private static List<Path> scripts() {
        try {
            return Scripts.loading();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    @Example
    void buildingEveryDiagramChangesNoByte() throws Exception {
        assertTrue(SCRIPTS.size() > 30, "scripts found: " + SCRIPTS.size());
        for (Path f : SCRIPTS) {
            String before = Files.readString(f);
            Program p = ScriptLoader.load(f, Map.of()).program();
            Diagrams.program(p).ifPresent(l -> org.parpe.core.diagram.Workbench.of(org.parpe.core.diagram.Layouts.program(l),
                    "free behaviors", org.parpe.core.diagram.Workbench.freeBehaviors(p), Map.of()));
            org.parpe.core.diagram.Workbench.of(new org.parpe.core.diagram.Scene(1, 1), "free automata",
                    org.parpe.core.diagram.Workbench.freeAutomata(p), Map.of());
            for (Behavior b : p.behaviors()) {
                Diagrams.swimlanes(p, b);
                for (Instance i : b.instances()) {
                    p.group(i.group().replace("!", "").trim()).ifPresent(g -> Diagrams.wheel(i, g));
                }
            }
            p.automata().forEach(a -> Diagrams.ring(p, a));
            assertEquals(before, new TextEdit(List.of()).apply(before), f.toString());
            assertEquals(before, Files.readString(f), f + " changed on disk");
        }
    }

    /** A random edit: a script, a kind and numbers that choose the node and the new value. */
    record Case(int script, int kind, int a, int b, int value) {
    }

    @Provide
    Arbitrary<Case> cases() {
        return Combinators.combine(Arbitraries.integers().between(0, SCRIPTS.size() - 1), Arbitraries.integers().between(0, 12),
                Arbitraries.integers().between(0, 1000), Arbitraries.integers().between(0, 1000),
                Arbitraries.integers().between(1, 4000)).as(Case::new);
    }

    @Property(tries = 300)
    void aDiagramEditIsTheHandEdit(@ForAll("cases") Case c) throws Exception {
        Path f = SCRIPTS.get(c.script());
        String text = Files.readString(f);
        LoadResult r = ScriptLoader.loadText(f, text, Map.of());
        Program p = r.program();
        String here = f.toString();
        String value = org.parpe.core.lang.Numbers.format(c.value() / 1000.0);
        String api;
        String hand;
        switch (c.kind()) {
            case 0 -> {
                List<Instance> all = new ArrayList<>();
                p.behaviors().forEach(b -> all.addAll(b.instances()));
                all.removeIf(i -> !i.pos().file().equals(here));
                if (all.isEmpty()) {
                    return;
                }
                Instance i = all.get(c.a() % all.size());
                String attr = c.b() % 2 == 0 ? "phase" : "offset";
                api = ScriptEdits.setAttribute(text, i.pos(), attr, value).apply(text);
                hand = HandEdits.setAttribute(text, i.pos().line(), i.pos().column(), attr, value);
            }
            case 1 -> {
                List<Automaton> all = new ArrayList<>(p.automata());
                all.removeIf(a -> !a.pos().file().equals(here) || a.pos().span() == null);
                if (all.isEmpty()) {
                    return;
                }
                Automaton a = all.get(c.a() % all.size());
                int s = c.b() % a.states().size();
                api = DiagramEdits.retime(text, a, s, value).apply(text);
                hand = HandEdits.retime(text, a.pos().line(), a.pos().column(), s, a.states().size(), value);
            }
            case 2 -> {
                if (p.main() == null || p.main().entries().isEmpty() || !p.main().pos().file().equals(here)) {
                    return;
                }
                List<MainEntry> es = p.main().entries();
                int from = c.a() % es.size();
                int to = c.b() % es.size();
                api = DiagramEdits.moveEntry(text, p.main(), from, to).apply(text);
                hand = HandEdits.moveEntry(text, es.stream().map(e -> new int[] {e.pos().line(), e.pos().column()}).toList(),
                        from, to);
            }
            case 4, 5, 6 -> {
                List<Automaton> all = new ArrayList<>(p.automata());
                all.removeIf(a -> a.table() || !a.pos().file().equals(here) || a.states().size() < 2);
                if (all.isEmpty()) {
                    return;
                }
                Automaton a = all.get(c.a() % all.size());
                int n = a.states().size();
                int s = c.b() % n;
                if (c.kind() == 4) {
                    api = RingEdits.removeState(text, a, s).apply(text);
                    hand = HandEdits.removeState(text, a.pos().line(), a.pos().column(), s);
                } else if (c.kind() == 5) {
                    api = RingEdits.moveState(text, a, s, c.value() % n).apply(text);
                    hand = HandEdits.moveState(text, a.pos().line(), a.pos().column(), s, c.value() % n);
                } else {
                    String exit = c.value() % 3 == 0 ? "" : "$cycle == " + c.value() % 7;
                    api = RingEdits.setExit(text, a, s, exit).apply(text);
                    hand = HandEdits.setExit(text, a.pos().line(), a.pos().column(), s, n, exit);
                }
            }
            case 7 -> {
                List<Behavior> all = new ArrayList<>(p.behaviors());
                all.removeIf(b -> !b.pos().file().equals(here));
                if (all.isEmpty() || p.automata().isEmpty() || p.robot().groups().isEmpty()) {
                    return;
                }
                Behavior b = all.get(c.a() % all.size());
                String aut = p.automata().get(c.b() % p.automata().size()).name();
                String group = p.robot().groups().get(c.value() % p.robot().groups().size()).name();
                api = BehaviorEdits.addInstance(text, b, aut, group).apply(text);
                SourcePos last = b.items().isEmpty() ? null : b.items().get(b.items().size() - 1).pos();
                hand = HandEdits.appendChild(text, b.pos().line(), b.pos().column(),
                        last == null ? null : new int[] {last.line(), last.column()}, "<" + aut + " group=\"" + group + "\"/>");
            }
            case 8 -> {
                if (p.main() == null || !p.main().pos().file().equals(here) || p.automata().isEmpty() || p.robot().groups().isEmpty()
                        || p.behaviors().stream().noneMatch(b -> b.pos().file().equals(here))) {
                    return;
                }
                String name = "added" + c.value();
                String aut = p.automata().get(c.b() % p.automata().size()).name();
                String group = p.robot().groups().get(c.a() % p.robot().groups().size()).name();
                String time = c.value() % 2 == 0 ? "" : value;
                api = BehaviorEdits.addBehavior(text, p, name, aut, group, time).apply(text);
                hand = handAddBehavior(text, p, here, name, aut, group, time);
            }
            case 12 -> {
                List<Behavior> plain = p.behaviors().stream().filter(b -> b.macros().isEmpty()).toList();
                if (p.main() == null || !p.main().pos().file().equals(here) || plain.isEmpty()) {
                    return;
                }
                String b = plain.get(c.a() % plain.size()).name();
                api = BehaviorEdits.addEntry(text, p, b).apply(text);
                List<MainEntry> es = p.main().entries();
                int[] last = es.isEmpty() ? null : new int[] {es.get(es.size() - 1).pos().line(),
                        es.get(es.size() - 1).pos().column()};
                hand = HandEdits.appendChild(text, p.main().pos().line(), p.main().pos().column(), last, "<" + b + "/>");
            }
            case 10 -> {
                List<StateDef> all = new ArrayList<>(p.states());
                all.removeIf(d -> !d.pos().file().equals(here) || d.pos().span() == null);
                String name = "pose" + c.value();
                if (all.isEmpty() || p.state(name).isPresent()) {
                    return;
                }
                StateDef last = all.get(all.size() - 1);
                api = PaletteEdits.addPose(text, p, name, value).apply(text);
                HandEdits.Tag t = HandEdits.tag(text, last.pos().line(), last.pos().column());
                int end = HandEdits.elementEnd(text, t);
                hand = HandEdits.replace(text, end, end, "\n" + HandEdits.indentOf(text, t.start()) + "<" + name + " angles=\""
                        + value + "\"/>");
            }
            case 11 -> {
                String name = "param" + c.value();
                if (p.parameters().stream().anyMatch(x -> x.name().equals(name))) {
                    return;
                }
                List<Parameter> mine = new ArrayList<>(p.parameters());
                mine.removeIf(x -> !x.pos().file().equals(here) || x.pos().span() == null);
                String element = "<" + name + " value=\"" + value + "\"/>";
                if (!mine.isEmpty()) {
                    Parameter last = mine.get(mine.size() - 1);
                    HandEdits.Tag t = HandEdits.tag(text, last.pos().line(), last.pos().column());
                    int end = HandEdits.elementEnd(text, t);
                    hand = HandEdits.replace(text, end, end, "\n" + HandEdits.indentOf(text, t.start()) + element);
                } else {
                    // no <parameters> yet: a new section right after <robot> (the only section before it), indented as that
                    if (text.contains("<parameters") || p.robot().pos() == null || !p.robot().pos().file().equals(here)) {
                        return;
                    }
                    HandEdits.Tag rt = HandEdits.tag(text, p.robot().pos().line(), p.robot().pos().column());
                    int end = HandEdits.elementEnd(text, rt);
                    String in = HandEdits.indentOf(text, rt.start());
                    hand = HandEdits.replace(text, end, end, "\n" + in + "<parameters>\n" + in + "  " + element + "\n" + in
                            + "</parameters>");
                }
                api = PaletteEdits.addParameter(text, p, name, value, "", " ", "").apply(text);
            }
            case 9 -> {
                List<StateDef> all = new ArrayList<>(p.states());
                all.removeIf(d -> !d.pos().file().equals(here) || d.pos().span() == null);
                if (all.isEmpty()) {
                    return;
                }
                StateDef d = all.get(c.a() % all.size());
                api = ScriptEdits.setAttribute(text, d.pos(), "angles", value).apply(text);
                hand = HandEdits.setAttribute(text, d.pos().line(), d.pos().column(), "angles", value);
            }
            default -> {
                List<Automaton> all = new ArrayList<>(p.automata());
                all.removeIf(a -> a.table() || !a.pos().file().equals(here) || p.states().isEmpty());
                if (all.isEmpty()) {
                    return;
                }
                Automaton a = all.get(c.a() % all.size());
                StateDef s = p.states().get(c.b() % p.states().size());
                String d = c.value() % 3 == 0 ? "1" : value;
                api = DiagramEdits.addState(text, p, a, s.name(), d).apply(text);
                hand = HandEdits.addState(text, a.pos().line(), a.pos().column(), a.states().size(), s.name(), d);
            }
        }
        assertEquals(hand, api, () -> "kind " + c.kind() + " on " + f);
        if (c.kind() != 3 && c.kind() < 6 || c.kind() >= 9) {
            LoadResult again = ScriptLoader.loadText(f, api, Map.of());
            assertTrue(again.ok() || c.kind() == 1, () -> "the edited text does not load: " + again.diagnostics());
        }
    }

    /**
     * The new behavior by hand: its element after the last behavior with that one's indentation,
     * its entry after {@code <main>}'s last; the later place in the text is edited first.
     */
    private static String handAddBehavior(String text, Program p, String file, String name, String aut, String group,
                                          String time) {
        Behavior lastB = p.behaviors().stream().filter(b -> b.pos().file().equals(file)).reduce((x, y) -> y).orElseThrow();
        HandEdits.Tag bt = HandEdits.tag(text, lastB.pos().line(), lastB.pos().column());
        int lineStart = text.lastIndexOf('\n', bt.start() - 1) + 1;
        String indent = text.substring(lineStart, bt.start()).isBlank() ? text.substring(lineStart, bt.start()) : "";
        int bEnd = HandEdits.elementEnd(text, bt);
        String def = "\n" + indent + "<" + name + ">\n" + indent + "  <" + aut + " group=\"" + group + "\"/>\n" + indent + "</"
                + name + ">";
        String entry = "<" + name + (time.isEmpty() ? "" : " time=\"" + time + "\"") + "/>";
        List<MainEntry> es = p.main().entries();
        int[] last = es.isEmpty() ? null : new int[] {es.get(es.size() - 1).pos().line(), es.get(es.size() - 1).pos().column()};
        int mainAt = HandEdits.offset(text, p.main().pos().line(), p.main().pos().column());
        if (mainAt < bEnd) {
            String withDef = HandEdits.replace(text, bEnd, bEnd, def);
            return HandEdits.appendChild(withDef, p.main().pos().line(), p.main().pos().column(), last, entry);
        }
        String withEntry = HandEdits.appendChild(text, p.main().pos().line(), p.main().pos().column(), last, entry);
        return HandEdits.replace(withEntry, bEnd, bEnd, def);
    }

    @Example
    void anAddedStateThatIsNotDefinedIsDefinedAfterTheLastState() throws Exception {
        Path f = Examples.dir().resolve("centipede-walk.xml");
        String text = Files.readString(f);
        Program p = ScriptLoader.load(f, Map.of()).program();
        Automaton swing = p.automaton("swing").orElseThrow();
        String edited = DiagramEdits.addState(text, p, swing, "hold", "0.5").apply(text);
        assertEquals(text.replace("states=\"reach, push\" times=\"1, 2\"", "states=\"reach, push, hold\" times=\"1, 2, 0.5\"")
                .replace("<stance angles=\"-press\"/>", "<stance angles=\"-press\"/>\n    <hold angles=\"0\"/>"), edited);
        Program q = ScriptLoader.loadText(f, edited, Map.of()).program();
        assertEquals(3, q.automaton("swing").orElseThrow().states().size());
    }

    @Example
    void ringEditsKeepEachStateWithItsTiming() throws Exception {
        Path f = Examples.dir().resolve("centipede-walk.xml");
        String text = Files.readString(f);
        Program p = ScriptLoader.load(f, Map.of()).program();
        Automaton step = p.automaton("step").orElseThrow();
        String line = "<step  states=\"raise, lower, stance\" times=\"0.5, 0.5, 2\"/>";
        assertEquals(text.replace(line, "<step  states=\"raise, stance\" times=\"0.5, 2\"/>"),
                RingEdits.removeState(text, step, 1).apply(text));
        assertEquals(text.replace(line, "<step  states=\"lower, stance\" times=\"0.5, 2\"/>"),
                RingEdits.removeState(text, step, 0).apply(text));
        assertEquals(text.replace(line, "<step  states=\"stance, raise, lower\" times=\"2, 0.5, 0.5\"/>"),
                RingEdits.moveState(text, step, 2, 0).apply(text));
        String exit = RingEdits.setExit(text, step, 2, "$cycle > 1").apply(text);
        assertEquals(text.replace(line, "<step  states=\"raise, lower, stance\" times=\"0.5, 0.5, 2[$cycle &gt; 1]\"/>"),
                exit);
        Automaton again = ScriptLoader.loadText(f, exit, Map.of()).program().automaton("step").orElseThrow();
        assertEquals(text, RingEdits.setExit(exit, again, 2, " ").apply(exit));
    }

    @Example
    void anAddedBehaviorIsDefinedAndRunFromMain() throws Exception {
        Path f = Examples.dir().resolve("centipede-walk.xml");
        String text = Files.readString(f);
        Program p = ScriptLoader.load(f, Map.of()).program();
        String edited = BehaviorEdits.addBehavior(text, p, "rest", "step", "spine", "2").apply(text);
        assertEquals(text.replace("    <walk/>\n", "    <walk/>\n    <rest time=\"2\"/>\n").replace("    </walk>\n",
                "    </walk>\n    <rest>\n      <step group=\"spine\"/>\n    </rest>\n"), edited);
        Program q = ScriptLoader.loadText(f, edited, Map.of()).program();
        assertEquals(List.of("walk", "rest"), q.main().entries().stream().map(MainEntry::behavior).toList());
        String more = BehaviorEdits.addInstance(edited, q.behavior("rest").orElseThrow(), "swing", "leftSwing").apply(edited);
        assertTrue(more.contains("      <step group=\"spine\"/>\n      <swing group=\"leftSwing\"/>\n    </rest>"), more);
        assertEquals(2, ScriptLoader.loadText(f, more, Map.of()).program().behavior("rest").orElseThrow().instances().size());
    }

    @Example
    void thePaletteDefinesEachThingAfterTheLastOfItsKind() throws Exception {
        Path f = Examples.dir().resolve("hello-snake.xml");
        String text = Files.readString(f);
        Program p = ScriptLoader.load(f, Map.of()).program();
        assertEquals(text.replace("<group2 elements=\"0,2,4,6\" />", "<group2 elements=\"0,2,4,6\" />\n      <tail elements=\"7..9\"/>"),
                PaletteEdits.addGroup(text, p, "tail", "7..9").apply(text));
        assertEquals(text.replace("<down angles=\"-30\" />", "<down angles=\"-30\" />\n    <flat angles=\"0\"/>"),
                PaletteEdits.addPose(text, p, "flat", "0").apply(text));
        assertEquals(text.replace("<wave states=\"up, down\" />", "<wave states=\"up, down\" />\n    <hop states=\"down, up\" times=\"1, 0.5\"/>"),
                PaletteEdits.addAutomaton(text, p, "hop", "down, up", "1, 0.5").apply(text));
        String table = PaletteEdits.addGaitTable(text, p, "travel", List.of("15, -15, 15, -15", "-15, 15, -15, 15"), "1, 1")
                .apply(text);
        assertEquals(text.replace("<wave states=\"up, down\" />", "<wave states=\"up, down\" />\n    <travel times=\"1, 1\">\n"
                + "      15, -15, 15, -15\n      -15, 15, -15, 15\n    </travel>"), table);
        assertEquals(2, ScriptLoader.loadText(f, table, Map.of()).program().automaton("travel").orElseThrow().states().size());
        assertEquals(text.replace("    <simpleWave />\n", ""), BehaviorEdits.removeEntry(text, p.main(), 0).apply(text));
        assertEquals("a state named 'up' exists already", org.junit.jupiter.api.Assertions.assertThrows(
                IllegalArgumentException.class, () -> PaletteEdits.addPose(text, p, "up", "1")).getMessage());
    }

    @Example
    void valuesAreWrittenAsXml() throws Exception {
        String text = "<program><robot><structure><b elements=\"0..3\"/></structure></robot>\n"
                + "<main><go time='2'/></main><behaviors><go><w group=\"b\"/></go></behaviors>\n"
                + "<automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states></program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
        SourcePos entry = p.main().entries().get(0).pos();
        String e1 = ScriptEdits.setAttribute(text, entry, "time", "$btime < 3 & \"x\" 'y'").apply(text);
        assertTrue(e1.contains("<go time='$btime &lt; 3 &amp; \"x\" &apos;y&apos;'/>"), e1);
        Instance w = p.behaviors().get(0).instances().get(0);
        String e2 = ScriptEdits.setAttribute(text, w.pos(), "phase", "a<b").apply(text);
        assertTrue(e2.contains("<w group=\"b\" phase=\"a&lt;b\"/>"), e2);
        String e3 = DiagramEdits.retime(text, p.automaton("w").orElseThrow(), 0, "0.5").apply(text);
        assertTrue(e3.contains("<w states=\"s\" times=\"0.5\"/>"), e3);
    }
}
