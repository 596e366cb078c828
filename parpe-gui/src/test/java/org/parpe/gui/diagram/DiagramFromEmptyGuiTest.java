package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.diagram.Projection.View;

/**
 * Issue 24, item 5: "a student can make the paper's Fig. 3 snake and Fig. 7 wheel from an empty
 * file without typing". Each test opens an empty file (0 bytes; a declaration and a comment;
 * white space only), as a student who made a new file does, and builds
 * {@code examples/hello-snake.xml}, {@code examples/wheel.xml} or
 * {@code examples/centipede-walk.xml} with the Diagram pane only: the start row's − and +
 * buttons, the palette, clicks on the diagram and the edit row's fields (a form; the script's
 * text is never typed into). The text made loads without errors and its trace is byte for byte
 * the example's (as {@link DiagramAcceptanceGuiTest} checks for the edits from File → New).
 */
class DiagramFromEmptyGuiTest {
    private static IdeWindow ide;
    private static DiagramDriver d;
    private static Path dir;

    @BeforeAll
    static void openWindow() throws Exception {
        d = DiagramDriver.open("parpe-diagram-empty");
        ide = d.ide();
        dir = Files.createTempDirectory("parpe-diagram-empty-files");
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    /**
     * Opens a file holding {@code empty} (File → Open), checks the pane offers the start of a
     * robot and no error, and starts one of {@code modules} modules in group {@code group} by
     * clicking − or + from the 8 offered.
     */
    private static void start(String name, String empty, int modules, String group) throws Exception {
        Path f = dir.resolve(name);
        Files.writeString(f, empty);
        IdeAccess.open(ide, f);
        d.front();
        d.show(View.PROGRAM, null);
        assertTrue(d.pane().message().startsWith("The file is empty. Start a robot"), d.pane().message());
        assertEquals(List.of("modules", "group"), List.copyOf(d.pane().fields().keySet()));
        assertEquals(Projection.START_MODULES, d.pane().fields().get("modules").getText());
        for (int n = Integer.parseInt(Projection.START_MODULES); n != modules; n += n < modules ? 1 : -1) {
            d.press(n < modules ? "modules+" : "modules\u2212");
        }
        assertEquals(Integer.toString(modules), d.pane().fields().get("modules").getText());
        assertEquals(empty, d.text(), "the − and + buttons change the form, not the text");
        d.press(Projection.START.text(), "group", group);
        assertTrue(d.text().startsWith(empty.strip()), "the declaration and comments stay:\n" + d.text());
        assertTrue(d.text().contains("<" + group + " elements=\"0.." + (modules - 1) + "\"/>"), d.text());
    }

    private static void palette(String item, String button, String... inputs) {
        assertTrue(d.pane().palette().items().contains(item), item + " is not in the palette shown: " + d.pane().palette().items());
        d.pane().palette().choose(item);
        d.press(button, inputs);
    }

    /**
     * The paper's one-automaton programs, from the beginner palette alone (issue 31: it had no
     * Automaton): {@code poses} (name, angles), automaton {@code wave} cycling through them in
     * that order with {@code times}, behavior {@code behavior} running it on {@code group} for
     * {@code time}; then the instance's bar in the lanes gets the {@code bar} fields (name, value pairs).
     */
    private static void wave(String[][] poses, String times, String behavior, String group, String time, String... bar) {
        d.pane().palette().full(false);
        for (String[] p : poses) {
            palette("Pose", "Add pose", "name", p[0], "angles", p[1]);
        }
        String states = String.join(", ", java.util.Arrays.stream(poses).map(p -> p[0]).toList());
        palette("Automaton", "Add automaton", "name", "wave", "add state", states, "times", times);
        palette("Behavior", "Add behavior", "behavior", behavior, "automaton", "wave", "group", group, "time", time);
        d.show(View.LANES, behavior);
        d.bar("<wave group=\"" + group + "\"", bar);
    }

    /** The trace of the built text equals the example's (6 s at the CLI's tick). */
    private static void sameTrace(String example) throws Exception {
        Path f = Path.of(example);
        String built = d.text();
        assertEquals(DiagramAcceptanceGuiTest.trace(f, DiagramAcceptanceGuiTest.example(example), 6),
                DiagramAcceptanceGuiTest.trace(f, built, 6), example + " built:\n" + built);
    }

    @Test
    void anEmptyFileOffersTheStartOfARobotAndNothingElse() throws Exception {
        Path f = dir.resolve("nothing.xml");
        Files.writeString(f, "<?xml version=\"1.0\"?>\n<!-- my first robot -->\n");
        IdeAccess.open(ide, f);
        d.front();
        for (View v : View.values()) {
            d.show(v, null);
            assertTrue(d.pane().message().startsWith("The file is empty. Start a robot"), v + ": " + d.pane().message());
            assertTrue(d.pane().actions().containsKey(Projection.START.text()), v + ": " + d.pane().actions().keySet());
        }
        d.show(View.PROGRAM, null);
        // what a student sees first: the beginner palette (the tests share one window, in any order)
        d.pane().palette().full(false);
        // issue 31: an empty file is a beginning, not an error; the status bar says how to begin
        IdeAccess.pump(() -> IdeAccess.status(ide).startsWith("The file is empty"), "the status bar saying the file is empty");
        assertEquals(List.of(), IdeAccess.problems(ide).shown(), "Problems lists no error beside the start of a robot");
        DiagramWindow.picture(ide, "diagram-empty-start.png");
        d.pane().palette().full(true);
        palette("Pose", "Add pose", "name", "up", "angles", "30");
        assertTrue(d.pane().message().startsWith("The file is empty: start a robot first"), d.pane().message());
        assertEquals("<?xml version=\"1.0\"?>\n<!-- my first robot -->\n", d.text(), "a refused item writes nothing");
        d.clickAside();
        assertTrue(d.pane().actions().containsKey(Projection.START.text()), "a click on the empty drawing brings the start back");
        d.pane().palette().full(false);
    }

    @Test
    void theFig3SnakeIsBuiltFromAnEmptyFile() throws Exception {
        start("snake.xml", "", 4, "group1");
        d.pane().palette().full(true);
        palette("Group", "Add group", "name", "group2", "elements", "0,2,4,6");
        d.pane().palette().full(false);
        wave(new String[][] {{"up", "30"}, {"down", "-30"}}, "", "simpleWave", "group1", "", "phase", "0.25", "period", "1",
                "elements", "0,2,4,6");
        sameTrace("hello-snake.xml");
        IdeAccess.screenshot(IdeAccess.shell(ide), "diagram-empty-built-fig3-snake.png");
    }

    @Test
    void theFig7WheelIsBuiltFromAnEmptyFile() throws Exception {
        start("wheel.xml", "<?xml version=\"1.0\" ?>\n<!-- The paper's cart wheel (Figs. 6 and 7) -->\n", 8, "wheel");
        wave(new String[][] {{"down", "-10"}, {"up", "45"}}, ".25, 1", "rotate", "wheel", "150", "phase", "0.25", "period", "2");
        sameTrace("wheel.xml");
        IdeAccess.screenshot(IdeAccess.shell(ide), "diagram-empty-built-fig7-wheel.png");
    }

    @Test
    void theCentipedeWalkIsBuiltFromAnEmptyFile() throws Exception {
        start("centipede.xml", "\n  \n", 7, "leftSwing");
        d.pane().palette().full(true);
        String[][] groups = {{"leftLift", "1, 3, 5, 7, 9, 11, 13"}, {"rightSwing", "14, 16, 18, 20, 22, 24, 26"},
            {"rightLift", "15, 17, 19, 21, 23, 25, 27"}, {"spine", "28..54"}};
        for (String[] g : groups) {
            palette("Group", "Add group", "name", g[0], "elements", g[1]);
        }
        String[][] parameters = {{"stride", "25", "0", "60", "Stride (degrees of swing)"}, {"lift", "20", "0", "80",
            "Leg lift (degrees)"}, {"press", "60", "0", "85", "Leg press in stance (degrees below level)"}};
        for (String[] p : parameters) {
            palette("Parameter", "Add parameter", "name", p[0], "value", p[1], "min", p[2], "max", p[3], "label", p[4]);
        }
        String[][] poses = {{"reach", "stride"}, {"push", "-stride"}, {"raise", "lift"}, {"lower", "-press"},
            {"stance", "-press"}};
        for (String[] p : poses) {
            palette("Pose", "Add pose", "name", p[0], "angles", p[1]);
        }
        palette("Automaton", "Add automaton", "name", "swing", "add state", "reach, push", "times", "1, 2");
        palette("Automaton", "Add automaton", "name", "step", "add state", "raise, lower, stance", "times", "0.5, 0.5, 2");
        palette("Behavior", "Add behavior", "behavior", "walk", "automaton", "swing", "group", "!leftSwing", "time", "");
        d.show(View.LANES, "walk");
        // the chain the robot started with becomes the left swing joints before the lift joints join the behavior
        d.bar("group=\"!leftSwing\"", "elements", "0, 2, 4, 6, 8, 10, 12", "phase", "0.75", "period", "3");
        String[][] instances = {{"swing", "rightSwing"}, {"step", "leftLift"}, {"step", "rightLift"}};
        for (String[] i : instances) {
            d.clickAside();
            d.press("Add instance", "automaton", i[0], "group", i[1]);
        }
        d.bar("group=\"rightSwing\"", "offset", "0.5", "phase", "0.75", "period", "3");
        d.bar("group=\"leftLift\"", "phase", "0.75", "period", "3");
        d.bar("group=\"rightLift\"", "offset", "0.5", "phase", "0.75", "period", "3");
        assertTrue(d.text().contains("  <parameters>\n    <stride value=\"25\" min=\"0\" max=\"60\" label=\"Stride (degrees of swing)\"/>"),
                d.text());
        sameTrace("centipede-walk.xml");
        IdeAccess.screenshot(IdeAccess.shell(ide), "diagram-empty-built-centipede.png");
    }
}
