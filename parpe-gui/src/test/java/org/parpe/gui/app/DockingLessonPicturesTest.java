package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.widgets.Display;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.automation.Screenshot;
import org.parpe.gui.run.RunOn;
import org.parpe.gui.run.Speed;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;

/**
 * Lesson 15's pictures of the docking snake in the 3D view (issue 35): before its ends meet
 * (dock reads 0), while they are drawn together (1) and after they have latched (2). The
 * moments are found by a run of the lesson without the IDE; the IDE then runs the lesson to
 * each moment in the simulator and its 3D view, with the two end modules highlighted, is drawn into
 * {@code docs/tutorial/img/15-docking-before.png}, {@code -during.png} and {@code -after.png}
 * (folder: system property {@code parpe.tutorialImages}).
 */
class DockingLessonPicturesTest {
    private static final int WIDTH = 640;
    private static final int HEIGHT = 420;
    private static Display display;
    private static IdeWindow ide;
    private static Path script;
    private static Path images;

    @BeforeAll
    static void openWindow() throws Exception {
        display = Gui.display();
        script = TutorialScreenshotsTest.tutorialFolder().resolve("15-docking-snake.xml");
        images = Path.of(System.getProperty("parpe.tutorialImages", "../docs/tutorial/img"));
        Files.createDirectories(images);
        ide = Gui.openIde(Files.createTempDirectory("parpe-docking-pictures"));
    }

    @AfterAll
    static void closeWindow() {
        if (ide != null && !ide.shell.isDisposed()) {
            Gui.endRun(ide);
            ide.shell.dispose();
        }
    }

    /** The first times at which both end plates read 1 (in reach) and 2 (latched), s. */
    private static double[] moments() throws Exception {
        LoadResult r = ScriptLoader.load(script, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        Run.Builder b = Run.builder(r.program(), new RunOptions(0.01, 0, List.of()), new DiagnosticList());
        SimTarget target = new SimTarget("snake:n=10");
        b.attach(target);
        Run run = b.duration(20).build();
        Simulator sim = target.simulator();
        double[] at = {-1, -1};
        run.engine().addObserver((tick, time, commanded) -> {
            int reading = Math.min(sim.dock(0, 0), sim.dock(9, 1));
            if (reading >= 1 && at[0] < 0) {
                at[0] = time;
            }
            if (reading == 2 && at[1] < 0) {
                at[1] = time;
                run.requestStop();
            }
        });
        run.execute();
        assertTrue(at[0] > 1 && at[1] > at[0], "the ends come within reach, then latch: " + at[0] + " s, " + at[1] + " s");
        return at;
    }

    @Test
    void theLessonsRobotBeforeDuringAndAfterLatching() throws Exception {
        double[] at = moments();
        int before = ide.validations();
        Gui.open(ide, script);
        Gui.pump(() -> ide.validations() > before && ide.program() != null, "the lesson to load");
        assertEquals(0L, ide.problems().errorCount(), () -> "problems: " + ide.problems().shown());
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(Speed.MAX);
        // well before the ends meet; halfway through the draw; a second after the latch closed
        picture("15-docking-before.png", at[0] - 2);
        picture("15-docking-during.png", (at[0] + at[1]) / 2);
        picture("15-docking-after.png", at[1] + 1);
    }

    /** Runs the lesson in the IDE for {@code seconds} and draws its 3D view into {@code name}. */
    private static void picture(String name, double seconds) throws Exception {
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        ide.runs.run(false, seconds, outcome::set);
        Gui.pump(() -> outcome.get() != null, seconds + " simulated seconds of the lesson", 180_000);
        assertNotEquals(RunOutcome.Status.ERROR, outcome.get().status(), outcome.get().message());
        assertEquals(seconds, outcome.get().time(), 0.02, "the run stopped where asked");
        Gui.pump(() -> !ide.runs.running(), "the run to wind up");
        // the same picture on every run: the camera framed on the pose, not easing towards it
        ide.view.setTrackRobot(false);
        ide.view.resetView();
        // the two end modules, whose plates latch, highlighted
        java.util.function.Supplier<java.util.Set<Integer>> driven = ide.view.highlighted();
        ide.view.setHighlighted(() -> java.util.Set.of(0, 9));
        Image image = new Image(display, WIDTH, HEIGHT);
        try {
            GC gc = new GC(image);
            try {
                ide.view.render(gc, WIDTH, HEIGHT);
            } finally {
                gc.dispose();
            }
            ImageData d = image.getImageData();
            assertTrue(Screenshot.distinctColours(d, 64) >= 64, name + " looks blank");
            Screenshot.write(d, images.resolve(name));
        } finally {
            image.dispose();
            ide.view.setHighlighted(driven);
            ide.view.setTrackRobot(true);
        }
    }
}
