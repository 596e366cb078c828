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
import org.parpe.core.diagram.DiagramEdits;
import org.parpe.core.diagram.Diagrams;
import org.parpe.core.diagram.TextEdit;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
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
            Diagrams.program(p);
            for (Behavior b : p.behaviors()) {
                Diagrams.swimlanes(p, b);
                for (Instance i : b.instances()) {
                    p.group(i.group().replace("!", "").trim()).ifPresent(g -> Diagrams.wheel(i, g));
                }
            }
            p.automata().forEach(Diagrams::ring);
            assertEquals(before, new TextEdit(List.of()).apply(before), f.toString());
            assertEquals(before, Files.readString(f), f + " changed on disk");
        }
    }

    /** A random edit: a script, a kind and numbers that choose the node and the new value. */
    record Case(int script, int kind, int a, int b, int value) {
    }

    @Provide
    Arbitrary<Case> cases() {
        return Combinators.combine(Arbitraries.integers().between(0, SCRIPTS.size() - 1), Arbitraries.integers().between(0, 3),
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
                api = DiagramEdits.setAttribute(text, i.pos(), attr, value).apply(text);
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
        if (c.kind() != 3) {
            LoadResult again = ScriptLoader.loadText(f, api, Map.of());
            assertTrue(again.ok() || c.kind() == 1, () -> "the edited text does not load: " + again.diagnostics());
        }
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
    void valuesAreWrittenAsXml() throws Exception {
        String text = "<program><robot><structure><b elements=\"0..3\"/></structure></robot>\n"
                + "<main><go time='2'/></main><behaviors><go><w group=\"b\"/></go></behaviors>\n"
                + "<automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states></program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
        SourcePos entry = p.main().entries().get(0).pos();
        String e1 = DiagramEdits.setAttribute(text, entry, "time", "$btime < 3 & \"x\" 'y'").apply(text);
        assertTrue(e1.contains("<go time='$btime &lt; 3 &amp; \"x\" &apos;y&apos;'/>"), e1);
        Instance w = p.behaviors().get(0).instances().get(0);
        String e2 = DiagramEdits.setAttribute(text, w.pos(), "phase", "a<b").apply(text);
        assertTrue(e2.contains("<w group=\"b\" phase=\"a&lt;b\"/>"), e2);
        String e3 = DiagramEdits.retime(text, p.automaton("w").orElseThrow(), 0, "0.5").apply(text);
        assertTrue(e3.contains("<w states=\"s\" times=\"0.5\"/>"), e3);
    }
}
