package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import org.parpe.gui.automation.Screenshot;
import org.parpe.gui.files.Examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.stream.Stream;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.ImageLoader;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Program;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.Speed;
import org.parpe.gui.run.RunOn;

/**
 * The tutorial's pictures, made by the IDE itself so that they never go stale: for every
 * {@code examples/tutorial/*.xml}, open it in the IDE, run it in the simulator (robot "auto",
 * which the lesson files' names pick) at maximum speed for a few simulated seconds, check that
 * the run went through with nothing in Problems, plot three of the modules it moves, and save
 * the window to
 * {@code docs/tutorial/img/NAME.png} (folder: system property {@code parpe.tutorialImages},
 * default {@code ../docs/tutorial/img} from the module). With {@code -Dparpe.tutorialLang=de}
 * (es, ja) the IDE speaks that language and the pictures are {@code NAME-de.png}, which Help →
 * Tutorial shows to a German student in place of {@code NAME.png}, and the lessons of
 * {@code docs/tutorial/de/} show; in a language only the lessons translated into it are pictured
 * ({@code de/01-poses.md}: the scripts {@code 01-*.xml}). One window for the whole class; every
 * wait is bounded.
 */
class TutorialScreenshotsTest {
    private static final long WAIT_MS = 30_000;
    /** Simulated seconds before the picture: far enough into every lesson to show it moving. */
    private static final double RUN_FOR = 8;
    private static Display display;
    private static IdeWindow ide;
    private static Path images;
    /** The language of the pictures: {@code ""} for English ({@code NAME.png}), else {@code -de} etc. */
    private static String suffix = "";

    static Path tutorialFolder() {
        Path examples = Examples.folder();
        assertNotNull(examples, "no examples folder (parpe.examples=" + System.getProperty("parpe.examples") + ")");
        return examples.resolve("tutorial");
    }

    static List<Path> scripts() throws IOException {
        Path dir = tutorialFolder();
        assertTrue(Files.isDirectory(dir), "no tutorial folder " + dir);
        try (Stream<Path> s = Files.list(dir)) {
            return s.filter(p -> p.getFileName().toString().endsWith(".xml")).sorted().toList();
        }
    }

    /**
     * The scripts pictured: every lesson's in English; in another language ({@code parpe.tutorialLang})
     * those of the lessons translated into it, whose numbers its folder beside the pictures' holds.
     */
    static List<Path> pictured() throws IOException {
        java.util.Locale lang = org.parpe.core.text.Lang.parse(System.getProperty("parpe.tutorialLang", "en"));
        if (lang == null || lang.equals(java.util.Locale.ENGLISH)) {
            return scripts();
        }
        Path lessons = Path.of(System.getProperty("parpe.tutorialImages", "../docs/tutorial/img")).resolveSibling(lang.getLanguage());
        Set<String> numbers = new TreeSet<>();
        try (Stream<Path> s = Files.list(lessons)) {
            s.map(p -> p.getFileName().toString()).filter(n -> n.matches("\\d\\d-.*\\.md")).forEach(n -> numbers.add(n.substring(0, 2)));
        }
        assertFalse(numbers.isEmpty(), "no translated lessons in " + lessons);
        return scripts().stream().filter(p -> numbers.contains(p.getFileName().toString().substring(0, 2))).toList();
    }

    @BeforeAll
    static void openWindow() throws Exception {
        String x = System.getenv("DISPLAY");
        if (x == null || x.isBlank()) {
            fail("No X display (DISPLAY is not set). The GUI tests need one: run them under xvfb-run, as ./test-all does.");
        }
        images = Path.of(System.getProperty("parpe.tutorialImages", "../docs/tutorial/img"));
        String lang = System.getProperty("parpe.tutorialLang", "en");
        java.util.Locale locale = org.parpe.core.text.Lang.parse(lang);
        assertNotNull(locale, "parpe.tutorialLang=" + lang + " is not one of " + org.parpe.core.text.Lang.codes());
        org.parpe.core.text.Lang.use(locale);
        suffix = locale.equals(java.util.Locale.ENGLISH) ? "" : "-" + locale.getLanguage();
        Files.createDirectories(images);
        Path home = Files.createTempDirectory("parpe-tutorial-test");
        display = Display.getDefault();
        ide = new IdeWindow(display, new Prefs(home));
        ide.open(null, true);
        pump(() -> ide.validations() > 0, "the first validation", WAIT_MS);
    }

    @AfterAll
    static void closeWindow() {
        if (ide != null && !ide.shell.isDisposed()) {
            ide.runs.stop();
            pump(() -> !ide.runs.running(), "the run to stop", WAIT_MS);
            ide.shell.dispose();
        }
        org.parpe.core.text.Lang.use(java.util.Locale.ENGLISH);
    }

    /** Runs the event loop until {@code done} holds; fails after {@code ms}. */
    private static void pump(BooleanSupplier done, String what, long ms) {
        Gui.pump(done, what, ms);
    }

    /** Lets the views catch up (the 3D view and the plots redraw on timers). */
    private static void settle(long ms) {
        long until = System.currentTimeMillis() + ms;
        pump(() -> System.currentTimeMillis() >= until, "the views to settle", ms + WAIT_MS);
    }

    /**
     * The modules of the groups that the behaviors of {@code <main>} drive, lowest first (taken
     * from the script rather than sampled during the run, which at maximum speed may be over
     * before the first sample, so that the picture is the same on every run).
     */
    private static Set<Integer> moved(Program program) {
        Set<Integer> ids = new TreeSet<>();
        program.mainDef().ifPresent(main -> {
            for (MainEntry entry : main.entries()) {
                program.behavior(entry.behavior()).ifPresent(b -> {
                    for (Instance i : b.instances()) {
                        String group = i.group().startsWith("!") ? i.group().substring(1) : i.group();
                        program.group(group).ifPresent(g -> ids.addAll(g.modules()));
                    }
                });
            }
        });
        return ids;
    }

    /**
     * Shows the first three modules the script moves in the Joint angles plot (by default it
     * shows the first three of the robot, which some lessons leave still).
     */
    private static void plotModules(Set<Integer> driven) {
        for (Control c : ((Composite) ide.plots.control()).getChildren()) {
            if (c instanceof org.eclipse.swt.widgets.List chooser) {
                chooser.deselectAll();
                int shown = 0;
                for (int id : driven) {
                    int at = chooser.indexOf("m" + id);
                    if (at >= 0 && shown < 3) {
                        chooser.select(at);
                        shown++;
                    }
                }
                if (shown == 0) {
                    chooser.select(0, Math.min(2, chooser.getItemCount() - 1));
                }
            }
        }
        ide.plots.refresh();
    }

    @Test
    void thereIsALessonScriptForEveryLesson() throws IOException {
        assertTrue(scripts().size() >= 10, "expected ten lesson scripts in " + tutorialFolder() + ", found " + scripts());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("pictured")
    void runsInTheSimulatorAndTakesTheLessonsPicture(Path script) throws Exception {
        String name = script.getFileName().toString();
        int before = ide.validations();
        Gui.open(ide, script);
        pump(() -> ide.validations() > before && ide.program() != null && ide.program().file().endsWith(name),
                name + " to load", WAIT_MS);
        assertEquals(0, ide.problems().errorCount(), name + " has errors: " + ide.problems().shown());

        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(Speed.MAX);
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        Set<Integer> driven = moved(ide.program());
        ide.runs.run(false, RUN_FOR, outcome::set);
        // The 55-module centipede is the slowest; allow for a busy machine.
        pump(() -> outcome.get() != null, RUN_FOR + " simulated seconds of " + name, 180_000);
        RunOutcome o = outcome.get();
        assertNotEquals(RunOutcome.Status.ERROR, o.status(), name + " failed: " + o.message());
        assertTrue(o.time() >= RUN_FOR - 0.02 || o.status() == RunOutcome.Status.COMPLETED,
                name + " stopped early at t = " + o.time());
        pump(() -> !ide.runs.running(), "the run of " + name + " to wind up", WAIT_MS);
        assertFalse(driven.isEmpty(), name + " moves no module");
        plotModules(driven);
        // A picture that is the same on every run, so that the build leaves the committed images
        // alone unless something really changed: the camera framed on the final pose rather than
        // eased towards it frame by frame, and no blinking caret in the editor.
        ide.view.setTrackRobot(false);
        ide.view.resetView();
        ide.view.control().setFocus();
        settle(800);
        assertEquals(0, ide.problems().errorCount(), name + " reported problems while running: " + ide.problems().shown());

        Path png = images.resolve(name.replaceFirst("\\.xml$", suffix + ".png"));
        Screenshot.save(ide.shell, png);
        ide.view.setTrackRobot(true);
        ImageData d = new ImageLoader().load(png.toString())[0];
        assertTrue(d.width > 600 && d.height > 400, "screenshot too small: " + d.width + "x" + d.height);
        assertTrue(Screenshot.distinctColours(d, 64) >= 64, "screenshot " + png + " looks blank");
    }
}
