package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.MenuItem;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Severity;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.TraceWriter;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.diagram.Projection.View;

/**
 * Issue 24's acceptance: starting from File → New, the paper's Fig. 3 snake
 * ({@code examples/hello-snake.xml}), its Fig. 7 wheel ({@code examples/wheel.xml}) and the
 * centipede walk ({@code examples/centipede-walk.xml})
 * are built with the Diagram pane only: the palette, clicks on the diagram, and the edit row's
 * fields and buttons (a form; nothing is typed into the script's text). The text made loads
 * without errors (as {@code parpe check}) and its trace, run by the engine at the CLI's tick for
 * the same time, is byte for byte the example's.
 */
class DiagramAcceptanceGuiTest {
    private static IdeWindow ide;
    private static DiagramDriver d;

    @BeforeAll
    static void openWindow() throws Exception {
        d = DiagramDriver.open("parpe-diagram-acceptance");
        ide = d.ide();
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    /** File → New from the menu bar, as a click on it does. */
    private static void fileNew() {
        for (MenuItem top : IdeAccess.shell(ide).getMenuBar().getItems()) {
            if (top.getText().replace("&", "").equals("File")) {
                for (MenuItem item : top.getMenu().getItems()) {
                    if (item.getText().replace("&", "").startsWith("New")) {
                        item.notifyListeners(SWT.Selection, new Event());
                    }
                }
            }
        }
        d.front();
        assertTrue(d.text().contains("<crawl/>"), "File > New gives the template");
    }

    /** The trace of {@code text} for {@code seconds} at the CLI's default tick. */
    static String trace(Path file, String text, double seconds) {
        LoadResult r = ScriptLoader.loadText(file, text, Map.of());
        assertTrue(r.diagnostics().stream().noneMatch(x -> x.severity() == Severity.ERROR), "check: " + r.diagnostics());
        double tick = 0.01;
        Engine e = new Engine(r.program(), new RunOptions(tick, 0, List.of()));
        StringWriter out = new StringWriter();
        e.addObserver(new TraceWriter(out));
        e.start();
        for (long k = 0; k * tick <= seconds + 1e-9 && e.step(); k++) {
            // the engine writes each tick's row to the trace
        }
        return out.toString();
    }

    static String example(String name) throws Exception {
        return Files.readString(Path.of(System.getProperty("parpe.examples", "../examples"), name));
    }

    @Test
    void theFig3SnakeIsBuiltByDiagramOnly() throws Exception {
        fileNew();
        d.show(View.PROGRAM, null);
        d.pane().palette().full(true);
        d.pane().palette().choose("Group");
        d.press("Add group", "name", "group1", "elements", "0,2,4,6");
        d.pane().palette().choose("Behavior");
        d.press("Add behavior", "behavior", "simpleWave", "automaton", "wave", "group", "group1", "time", "");
        // the lanes of the new behavior show (issue 31); the entry to remove is on the program lane
        d.show(View.PROGRAM, null);
        d.click(d.node("<crawl/>"));
        d.press("Remove entry");
        d.show(View.LANES, "simpleWave");
        d.bar("<wave group=\"group1\"", "phase", "0.25", "period", "1");
        d.show(View.LANES, "crawl");
        d.bar("<wave group=\"body\"", "elements", "0,2,4,6");
        String built = d.text();
        Path f = Path.of("hello-snake.xml");
        assertEquals(trace(f, example("hello-snake.xml"), 6), trace(f, built, 6), "the snake's trace:\n" + built);
        IdeAccess.screenshot(IdeAccess.shell(ide), "diagram-built-fig3-snake.png");
        d.show(View.LANES, "simpleWave");
        d.bar("<wave group=\"group1\"");
        d.press("Expand to gait table", "table", "waveTable");
        assertTrue(d.text().contains("<waveTable group=\"group1\" phase=\"0\" period=\"1\"/>"), d.text());
        String[] snake = trace(f, example("hello-snake.xml"), 3).split("\n");
        String[] table = trace(f, d.text(), 3).split("\n");
        assertEquals(snake.length, table.length);
        // from one period (1 s, row 101) on the table drives the modules as the automaton did
        for (int r = 102; r < snake.length; r++) {
            String[] a = snake[r].split(",");
            String[] b = table[r].split(",");
            for (int c = 0; c < a.length; c++) {
                assertEquals(Double.parseDouble(a[c]), Double.parseDouble(b[c]), 1e-6, snake[r] + " / " + table[r]);
            }
        }
    }

    @Test
    void theCentipedeWalkIsBuiltByDiagramOnly() throws Exception {
        fileNew();
        d.show(View.PROGRAM, null);
        d.pane().palette().full(true);
        String[][] groups = {{"leftSwing", "0, 2, 4, 6, 8, 10, 12"}, {"leftLift", "1, 3, 5, 7, 9, 11, 13"},
            {"rightSwing", "14, 16, 18, 20, 22, 24, 26"}, {"rightLift", "15, 17, 19, 21, 23, 25, 27"}, {"spine", "28..54"}};
        for (String[] g : groups) {
            d.pane().palette().choose("Group");
            d.press("Add group", "name", g[0], "elements", g[1]);
        }
        d.pane().palette().full(false);
        String[][] poses = {{"reach", "25"}, {"push", "-25"}, {"raise", "20"}, {"lower", "-60"}, {"stance", "-60"}};
        for (String[] p : poses) {
            d.pane().palette().choose("Pose");
            d.press("Add pose", "name", p[0], "angles", p[1]);
        }
        d.pane().palette().full(true);
        d.pane().palette().choose("Automaton");
        d.press("Add automaton", "name", "swing", "add state", "reach, push", "times", "1, 2");
        d.pane().palette().choose("Automaton");
        d.press("Add automaton", "name", "step", "add state", "raise, lower, stance", "times", "0.5, 0.5, 2");
        d.pane().palette().choose("Behavior");
        d.press("Add behavior", "behavior", "walk", "automaton", "swing", "group", "!leftSwing", "time", "");
        String[][] instances = {{"swing", "rightSwing"}, {"step", "leftLift"}, {"step", "rightLift"}};
        for (String[] i : instances) {
            d.pane().palette().choose("Instance");
            d.press("Add instance", "behavior", "walk", "automaton", i[0], "group", i[1]);
        }
        d.show(View.PROGRAM, null);
        d.click(d.node("<crawl/>"));
        d.press("Remove entry");
        d.show(View.LANES, "walk");
        d.bar("group=\"!leftSwing\"", "phase", "0.75", "period", "3");
        d.bar("group=\"rightSwing\"", "offset", "0.5", "phase", "0.75", "period", "3");
        d.bar("group=\"leftLift\"", "phase", "0.75", "period", "3");
        d.bar("group=\"rightLift\"", "offset", "0.5", "phase", "0.75", "period", "3");
        String built = d.text();
        Path f = Path.of("centipede-walk.xml");
        assertEquals(trace(f, example("centipede-walk.xml"), 6), trace(f, built, 6), "the centipede's trace:\n" + built);
        IdeAccess.screenshot(IdeAccess.shell(ide), "diagram-built-centipede.png");
    }

    @Test
    void theFig7WheelIsBuiltByDiagramOnly() throws Exception {
        fileNew();
        String template = d.text();
        d.show(View.RING, "wave");
        d.click(d.node("<down "));
        d.press("Earlier");
        d.click(d.node("<down "));
        d.type("duration", ".25");
        d.click(d.node("<down "));
        d.type("angles", "-10");
        d.click(d.node("<up "));
        d.type("angles", "45");
        d.show(View.PROGRAM, null);
        d.click(d.node("<crawl/>"));
        d.type("time", "150");
        String built = d.text();
        Path f = Path.of("wheel.xml");
        assertEquals(trace(f, example("wheel.xml"), 6), trace(f, built, 6), "the wheel's trace:\n" + built);
        assertNotEquals(trace(f, template, 6), trace(f, built, 6), "the comparison sees the difference the edits make");
        IdeAccess.screenshot(IdeAccess.shell(ide), "diagram-built-fig7-wheel.png");
    }
}
