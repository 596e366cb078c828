package org.parpe.gui.grade;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.ImageLoader;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.gui.app.Gui;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.automation.Screenshot;
import org.parpe.sim.snapshot.SimSnapshot;

/**
 * Issue 37, item 4: the Class window grades a folder (three good scripts, one that does not
 * load) with real widgets, shows the ranking as {@code parpe grade} ranks it, and replays a
 * student's run from its trace in the 3D view beside that student's script. Makes
 * {@code docs/images/class-window.png} at 1366×768 (folder: system property {@code parpe.ideImages},
 * default {@code ../docs/images}).
 */
class ClassWindowGuiTest {
    private static final long GRADING_MS = 180_000;
    private IdeWindow ide;
    private ClassWindow window;

    @AfterEach
    void close() {
        if (window != null && !window.shell().isDisposed()) {
            window.shell().dispose();
        }
        Gui.closeIde(ide);
    }

    static String snake(String bend) {
        return "<program>\n  <robot><structure><body elements=\"0..7\"/></structure></robot>\n"
                + "  <main><race/></main>\n"
                + "  <behaviors><race><wave group=\"body\" phase=\"0.2\" period=\"1.5\"/></race></behaviors>\n"
                + "  <automata><wave states=\"up, down\"/></automata>\n"
                + "  <states><up angles=\"" + bend + "\" interp=\"smooth\"/><down angles=\"-" + bend
                + "\" interp=\"smooth\"/></states>\n</program>\n";
    }

    private static MenuItem item(Menu menu, String prefix) {
        return Arrays.stream(menu.getItems()).filter(i -> i.getText().replace("&", "").startsWith(prefix)).findFirst()
                .orElse(null);
    }

    @Test
    void theRunMenuOpensTheClassWindow() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-class-menu"));
        MenuItem run = item(IdeAccess.shell(ide).getMenuBar(), "Run");
        MenuItem grade = item(run.getMenu(), "Grade a Class");
        assertNotNull(grade, "no Run > Grade a Class… item");
        grade.notifyListeners(SWT.Selection, new Event());
        grade.notifyListeners(SWT.Selection, new Event());
        Shell[] open = Arrays.stream(IdeAccess.shell(ide).getShells()).filter(s -> !s.isDisposed() && s.getText().startsWith("Class"))
                .toArray(Shell[]::new);
        assertEquals(1, open.length, "a second click brings the same window");
        assertTrue(open[0].isVisible());
    }

    @Test
    void gradesAFolderShowsTheRankingAndReplaysARun() throws Exception {
        Path dir = Files.createTempDirectory("parpe-class");
        Path students = Files.createDirectories(dir.resolve("class-3b"));
        Files.writeString(students.resolve("ada.xml"), snake("45"));
        Files.writeString(students.resolve("ben.xml"), snake("15"));
        Files.writeString(students.resolve("cleo.xml"), snake("30"));
        Files.writeString(students.resolve("dan.xml"), snake("30").replace("<automata>", "<automaton>")
                .replace("</automata>", "</automaton>"));
        Path world = Path.of(System.getProperty("parpe.examples", "../examples"), "worlds", "race-track.xml")
                .toAbsolutePath().normalize();
        Path challenge = Files.writeString(dir.resolve("race.xml"), "<challenge world=\"" + world
                + "\" robot=\"snake:n=8\" duration=\"3\" tick=\"0.01\" max-modules=\"8\" tie-break=\"distance\"/>\n");
        ide = Gui.openIde(Files.createTempDirectory("parpe-class-home"));
        window = ClassWindow.open(IdeAccess.shell(ide));
        window.load(challenge, students);
        assertEquals("", window.message(), "the challenge loads");
        assertTrue(window.controls().grade().isEnabled());
        window.controls().grade().notifyListeners(SWT.Selection, new Event());
        assertTrue(window.running() && window.controls().stop().isEnabled(), "grading runs off the UI thread");
        Gui.pump(() -> !window.running(), "the class to be graded", GRADING_MS);
        assertEquals(4, window.controls().progress().getSelection());

        List<String> names = window.controls().ranking().rows().stream().map(r -> r.student().name()).toList();
        assertEquals(4, names.size(), window.message());
        assertEquals("dan.xml", names.get(3), "the script that does not load is last");
        String[] dan = RankingTable.cells(window.controls().ranking().rows().get(3));
        assertEquals("-", dan[0]);
        assertTrue(dan[8].matches("dan\\.xml:\\d+:\\d+: error: unknown section <automaton>.*"), dan[8]);
        for (int i = 0; i < 3; i++) {
            String[] cells = RankingTable.cells(window.controls().ranking().rows().get(i));
            assertEquals(Integer.toString(i + 1), cells[0], "ranks 1, 2, 3: " + Arrays.toString(cells));
            assertEquals(List.of(cells), texts(window, i), "the table shows the row's cells");
        }
        double s1 = window.controls().ranking().rows().get(0).outcome().score();
        double s3 = window.controls().ranking().rows().get(2).outcome().score();
        assertTrue(s1 >= s3, "ranked by score: " + s1 + " then " + s3);
        assertTrue(window.message().startsWith("4 students: 3 ranked, 1 with problems"), window.message());
        Path report = dir.resolve("class-3b-report");
        assertTrue(Files.isRegularFile(report.resolve("report.html")) && Files.isRegularFile(report.resolve("report.csv")));

        IdeAccess.shell(ide).setBounds(1400, 0, 200, 200); // not behind the picture where the window's trim would be
        window.shell().setBounds(0, 0, 1366, 768);
        window.controls().ranking().control().setSelection(0);
        window.controls().ranking().control().notifyListeners(SWT.Selection, new Event());
        assertNotNull(window.player(), "selecting a ranked student replays its run");
        assertEquals(Files.readString(students.resolve(names.get(0))), window.controls().script().getText(), "beside its script");
        Gui.pump(() -> {
            SimSnapshot s = window.controls().view().lastSnapshot();
            return s != null && s.time() >= 1.5;
        }, "1.5 s of the replay in the 3D view", 30_000);
        assertTrue(window.controls().view().frames() > 0);
        assertTrue(window.controls().view().hudText().startsWith("replay of ada.xml   t = "), window.controls().view().hudText());
        assertTrue(window.message().startsWith("4 students: 3 ranked"), "the summary stays: " + window.message());

        Path images = Path.of(System.getProperty("parpe.ideImages", "../docs/images"));
        Files.createDirectories(images);
        Path png = images.resolve("class-window.png");
        Gui.settle();
        Screenshot.save(window.shell(), png);
        ImageData d = new ImageLoader().load(png.toString())[0];
        assertArrayEquals(new int[] {1366, 768}, new int[] {d.width, d.height});
        assertTrue(Screenshot.distinctColours(d, 64) >= 64, png + " looks blank");

        window.controls().ranking().control().setSelection(3);
        window.controls().ranking().control().notifyListeners(SWT.Selection, new Event());
        assertTrue(window.controls().problem().getText().contains("unknown section <automaton>"), window.controls().problem().getText());
    }

    @Test
    void stopEndsTheGradingAndItsRuns() throws Exception {
        Path dir = Files.createTempDirectory("parpe-class-stop");
        Path students = Files.createDirectories(dir.resolve("class"));
        for (String name : List.of("a.xml", "b.xml", "c.xml")) {
            Files.writeString(students.resolve(name), snake("30").replace("<main>", "<main cycles=\"forever\">"));
        }
        Path world = Path.of(System.getProperty("parpe.examples", "../examples"), "worlds", "race-track.xml")
                .toAbsolutePath().normalize();
        Path challenge = Files.writeString(dir.resolve("race.xml"), "<challenge world=\"" + world
                + "\" robot=\"snake:n=8\" duration=\"3600\"/>\n");
        ide = Gui.openIde(Files.createTempDirectory("parpe-class-home"));
        window = ClassWindow.open(IdeAccess.shell(ide));
        window.load(challenge, students);
        window.controls().grade().notifyListeners(SWT.Selection, new Event());
        Gui.pump(() -> ProcessHandle.current().children().findAny().isPresent(), "a student's run to start", 60_000);
        assertTrue(window.controls().stop().isEnabled());
        window.controls().stop().notifyListeners(SWT.Selection, new Event());
        Gui.pump(() -> !window.running(), "the grading to stop", 60_000);
        assertEquals("grading stopped", window.message());
        Gui.pump(() -> ProcessHandle.current().children().findAny().isEmpty(), "no run left", 30_000);
        assertTrue(window.controls().grade().isEnabled(), "the class can be graded again");
    }

    private static List<String> texts(ClassWindow w, int row) {
        String[] t = new String[RankingTable.titles().length];
        for (int k = 0; k < t.length; k++) {
            t[k] = w.controls().ranking().control().getItem(row).getText(k);
        }
        return List.of(t);
    }
}
