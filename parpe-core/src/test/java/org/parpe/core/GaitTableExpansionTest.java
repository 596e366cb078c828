package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import org.parpe.core.diagram.Diagrams;
import org.parpe.core.diagram.GaitTableExpansion;
import org.parpe.core.diagram.PaletteEdits;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Group;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Program;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.TraceWriter;

/**
 * "Expand to gait table" against the engine: an example's instance replaced by the table
 * {@link GaitTableExpansion} makes (written into the text here by hand: the instance's element
 * renamed to the table, the table added by the palette) gives the same trace, run by the same
 * engine, from one period on (PARSL.md §7.1: before that the automaton starts each module
 * part-way into a state, which a table cannot).
 */
class GaitTableExpansionTest {

    private static String trace(Path f, String text, double seconds) {
        LoadResult r = ScriptLoader.loadText(f, text, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString() + "\n" + text);
        double tick = 0.01;
        Engine e = new Engine(r.program(), new RunOptions(tick, 0, List.of()));
        StringWriter out = new StringWriter();
        e.addObserver(new TraceWriter(out));
        e.start();
        for (long k = 0; k * tick <= seconds + 1e-9 && e.step(); k++) {
            // each tick writes its row
        }
        return out.toString();
    }

    /** The rows of {@code trace} from time {@code from} on, each as its numbers. */
    private static List<double[]> from(String trace, double from) {
        List<double[]> out = new ArrayList<>();
        for (String line : trace.strip().split("\n")) {
            if (line.startsWith("time")) {
                continue;
            }
            String[] cells = line.split(",");
            double[] v = new double[cells.length];
            for (int i = 0; i < v.length; i++) {
                v[i] = Double.parseDouble(cells[i]);
            }
            if (v[0] >= from - 1e-9) {
                out.add(v);
            }
        }
        return out;
    }

    /** An example, its text and program, and its first behavior's first instance with its group. */
    private record First(Path file, String text, Program p, Instance in, Group g) {
    }

    private static First first(String example) throws Exception {
        Path f = Examples.dir().resolve(example);
        Program p = ScriptLoader.load(f, Map.of()).program();
        Behavior b = p.behaviors().get(0);
        Instance in = b.instances().get(0);
        return new First(f, Files.readString(f), p, in, Diagrams.groupOf(p, b, in).orElseThrow());
    }

    @ParameterizedTest
    @CsvSource({"hello-snake.xml, <wave group=\"group1\" phase=\"0.25\" period=\"1\" />, 1",
        "wheel.xml, <wave group=\"wheel\" phase=\"0.25\" period=\"2\" />, 2"})
    void theExpandedTableDrivesTheModulesAsTheAutomatonDoes(String example, String element, double period) throws Exception {
        Path f = Examples.dir().resolve(example);
        String text = Files.readString(f);
        Program p = ScriptLoader.load(f, Map.of()).program();
        Behavior b = p.behaviors().get(0);
        Instance in = b.instances().get(0);
        GaitTableExpansion.Table t = GaitTableExpansion.expand(p, in, Diagrams.groupOf(p, b, in).orElseThrow());
        String withTable = PaletteEdits.addGaitTable(text, p, "expanded", t.rowTexts(), t.times()).apply(text);
        assertTrue(withTable.contains(element), element);
        String played = withTable.replace(element, element.replace("<wave ", "<expanded ").replaceAll(" phase=\"[^\"]*\"", "")
                .replaceAll(" period=\"[^\"]*\"", ""));
        double seconds = 3 * period;
        List<double[]> expected = from(trace(f, text, seconds), period);
        List<double[]> got = from(trace(f, played, seconds), period);
        assertEquals(expected.size(), got.size());
        for (int r = 0; r < expected.size(); r++) {
            for (int c = 0; c < expected.get(r).length; c++) {
                assertEquals(expected.get(r)[c], got.get(r)[c], 1e-6, "t=" + expected.get(r)[0] + " column " + c + "\n" + played);
            }
        }
        assertNotEquals(trace(f, text, period), trace(f, played, period), "in the first period the automaton starts part-way");
    }

    @Test
    void expandingWritesTheTableAndTheInstancePlaysIt() throws Exception {
        First x = first("hello-snake.xml");
        String written = GaitTableExpansion.write(x.text(), x.p(), x.in(), x.g(), "waveTable").apply(x.text());
        GaitTableExpansion.Table t = GaitTableExpansion.expand(x.p(), x.in(), x.g());
        assertEquals(PaletteEdits.addGaitTable(x.text(), x.p(), "waveTable", t.rowTexts(), t.times()).apply(x.text()).replace(
                "<wave group=\"group1\" phase=\"0.25\" period=\"1\" />", "<waveTable group=\"group1\" phase=\"0\" period=\"1\" />"),
                written);
        assertEquals(4, t.rows().size(), "a row for each quarter: the four modules enter a state a quarter apart");
        List<double[]> expected = from(trace(x.file(), x.text(), 3), 1);
        List<double[]> got = from(trace(x.file(), written, 3), 1);
        for (int r = 0; r < expected.size(); r++) {
            assertEquals(expected.get(r)[1], got.get(r)[1], 1e-6, "module 0 at t=" + expected.get(r)[0]);
        }
    }

    @Test
    void theExpandedSnakeTableIsAPhaseAutomatonAgain() throws Exception {
        First x = first("hello-snake.xml");
        String written = GaitTableExpansion.write(x.text(), x.p(), x.in(), x.g(), "waveTable").apply(x.text());
        Program q = ScriptLoader.loadText(x.file(), written, Map.of()).program();
        GaitTableExpansion.Cycle c = GaitTableExpansion.cycleOf(q.automaton("waveTable").orElseThrow(), x.g().size());
        assertEquals(0.25, c.phase(), 1e-12, "one row of four per module: the snake's quarter");
        assertEquals(4, c.angles().length);
        assertEquals(1.0, java.util.Arrays.stream(c.seconds()).sum(), 1e-12);
    }

    @Test
    void thePapersGaitTableIsAPhaseAutomatonWithAnEighthOfACycleBetweenModules() throws Exception {
        Path f = Examples.dir().resolve("gait-table-12.xml");
        Program p = ScriptLoader.load(f, Map.of()).program();
        // each of its 12 columns is the one before it moved down one of its 8 rows
        GaitTableExpansion.Cycle c = GaitTableExpansion.cycleOf(p.automaton("travel").orElseThrow(), 12);
        assertEquals(0.125, c.phase(), 1e-12);
        assertEquals(List.of(15.0, -15.0, -15.0, -15.0, -15.0, 15.0, 15.0, 15.0),
                java.util.Arrays.stream(c.angles()).boxed().toList());
    }

    @Test
    void thePapersTableMadeAPhaseAutomatonRunsTheSameTrace() throws Exception {
        First x = first("gait-table-12.xml");
        String made = GaitTableExpansion.writeCycle(x.text(), x.p(), x.in(), x.g(), "travelCycle").apply(x.text());
        Program q = ScriptLoader.loadText(x.file(), made, Map.of()).program();
        assertEquals(List.of("travelCycle_0", "travelCycle_1", "travelCycle_1", "travelCycle_1", "travelCycle_1", "travelCycle_0",
                "travelCycle_0", "travelCycle_0"), q.automaton("travelCycle").orElseThrow().states().stream()
                .map(org.parpe.core.model.StateDef::name).toList());
        // the table's modules all start at its first row, the automaton's at their phase: the same places
        assertEquals(trace(x.file(), x.text(), 10), trace(x.file(), made, 10));
        assertTrue(made.contains("<travelCycle group="), made);
        // the new <states> right after the <automata> that holds the table (found by its span), indented as it
        assertTrue(made.contains("  </automata>\n  <states>\n    <travelCycle_0 angles=\"15\"/>\n"
                + "    <travelCycle_1 angles=\"-15\"/>\n  </states>"), made);
    }

    @Test
    void aTableWhoseColumnsAreNotOneShiftedSequenceIsNoPhaseAutomaton() {
        String text = "<program><robot><structure><b elements=\"0, 1\"/></structure></robot>\n"
                + "<main><go/></main><behaviors><go><t group=\"b\"/></go></behaviors>\n"
                + "<automata><t>\n10, 20\n30, 40\n</t></automata></program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
        var e = assertThrows(IllegalArgumentException.class, () -> GaitTableExpansion.cycleOf(p.automaton("t").orElseThrow(), 2));
        assertTrue(e.getMessage().contains("no phase automaton"), e.getMessage());
    }

    @Test
    void anInstanceThatIsNotAFixedCycleIsRefusedWithTheReason() throws Exception {
        Path f = Examples.dir().resolve("sensor-exit.xml");
        Program p = ScriptLoader.load(f, Map.of()).program();
        Behavior b = p.behaviors().get(0);
        Instance in = b.instances().get(0);
        var e = assertThrows(IllegalArgumentException.class,
                () -> GaitTableExpansion.expand(p, in, Diagrams.groupOf(p, b, in).orElseThrow()));
        assertTrue(e.getMessage().contains("exit condition") || e.getMessage().contains("known only while running"), e.getMessage());
    }

    /**
     * An instance that starts late or stops after some cycles plays no repeating table: refused;
     * the same instance without them expands. (Every attribute of {@link Instance} is read or
     * refused by {@code expand}: a new one does not compile there until it says which.)
     */
    @ParameterizedTest
    @CsvSource({"start=\"1\"", "cycles=\"2\""})
    void anInstanceThatStartsLateOrStopsIsRefused(String attribute) {
        String text = "<program><robot><structure><b elements=\"0, 1\"/></structure></robot>\n"
                + "<main><go/></main><behaviors><go><wave group=\"b\" " + attribute + "/></go></behaviors>\n"
                + "<automata><wave states=\"up, down\"/></automata>\n"
                + "<states><up angles=\"30\"/><down angles=\"-30\"/></states></program>";
        Program p = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of()).program();
        Behavior b = p.behaviors().get(0);
        var e = assertThrows(IllegalArgumentException.class,
                () -> GaitTableExpansion.expand(p, b.instances().get(0), Diagrams.groupOf(p, b, b.instances().get(0)).orElseThrow()));
        assertTrue(e.getMessage().contains("start or cycles"), e.getMessage());
        Program plain = ScriptLoader.loadText(Path.of("t.xml"), text.replace(attribute, ""), Map.of()).program();
        Behavior pb = plain.behaviors().get(0);
        assertEquals(2, GaitTableExpansion.expand(plain, pb.instances().get(0),
                Diagrams.groupOf(plain, pb, pb.instances().get(0)).orElseThrow()).rows().size());
    }
}
