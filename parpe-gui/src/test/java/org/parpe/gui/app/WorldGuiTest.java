package org.parpe.gui.app;

import org.parpe.gui.view3d.ModuleCameraWindow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.widgets.Display;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.Speed;
import org.parpe.gui.run.RunOn;
import org.parpe.gui.view3d.ModuleCameraView;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.world.World;

/**
 * The world picker beside the robot picker: each example world chosen in the IDE is what the
 * robot runs in, and the 3D view draws its scenery and objects (screenshots
 * {@code world-NAME.png} in the test artefacts); the module camera shows the world from the
 * snake's head ({@code camera-NAME.png}).
 */
class WorldGuiTest {
    @TempDir
    static Path home;
    static IdeWindow ide;

    /** The least share of the module camera's picture that the world ahead of the head covers. */
    private static final double MIN_WORLD_IN_CAMERA = 0.10;

    private static ImageData render(ModuleCameraView view, SimSnapshot snap) {
        Image img = new Image(Display.getCurrent(), 320, 240);
        GC gc = new GC(img);
        try {
            view.setSource(() -> snap);
            view.render(gc, 320, 240);
            return img.getImageData();
        } finally {
            gc.dispose();
            img.dispose();
            view.setSource(ide.runs::snapshot);
        }
    }

    private static double differing(ImageData a, ImageData b) {
        int n = 0;
        for (int y = 0; y < a.height; y++) {
            for (int x = 0; x < a.width; x++) {
                if (a.getPixel(x, y) != b.getPixel(x, y)) {
                    n++;
                }
            }
        }
        return (double) n / (a.width * a.height);
    }

    @BeforeAll
    static void open() {
        ide = Gui.openIde(home);
        ide.shell.setSize(1480, 920);
    }

    @AfterAll
    static void close() {
        Gui.closeIde(ide);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"race-track, worlds/race-track-snake.xml", "rubble, tutorial/12-rubble-snake.xml",
        "slot-machine, tutorial/13-slot-machine-snake.xml"})
    void aChosenWorldIsRunAndDrawn(String world, String script) throws Exception {
        Gui.open(ide, Gui.example(script));
        ide.viewBar.world().choose(Gui.example("worlds/" + world + ".xml"));
        World w = ide.viewBar.world().world();
        assertTrue(w != null, world + " did not load");
        ide.runs.invalidatePreview();
        ide.runs.updatePreview(ide.program());
        // the preview (the robot at the world's start) is built in the background: wait for it
        Gui.pump(() -> ide.runs.snapshot() != null && ide.runs.snapshot().scenery().size() > 0,
                "the preview in " + world);
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(Speed.MAX);
        AtomicReference<RunOutcome> end = new AtomicReference<>();
        ide.runs.run(false, 12, end::set);
        Gui.pump(() -> end.get() != null, "the run in " + world);
        Gui.settle();
        SimSnapshot s = ide.runs.snapshot();
        assertTrue(s.time() > 11.9, "the view shows the end of the run, t = " + s.time() + "; " + end.get() + "; " + ide.status.message());
        long solids = s.scenery().stream().filter(b -> b.kind() == PartKind.SCENERY).count();
        long pieces = w.objects().stream().mapToLong(o -> o.pieces().size()).sum();
        assertEquals(w.solids().size(), solids, "the world's solids are in the snapshot the view draws");
        assertEquals(pieces, s.scenery().size() - solids, "and its objects' pieces");
        assertTrue(s.centerOfMass().x() > 0.4, "the robot started at the world's start and moved: " + s.centerOfMass());
        assertTrue(ide.status.message().startsWith("Score "), "the status gives the score first: " + ide.status.message());
        Gui.screenshot(ide.shell, "world-" + world + ".png");
        ModuleCameraWindow camera = ide.openModuleCamera();
        try {
            camera.shell().setSize(720, 520);
            camera.setModule(7);
            Gui.settle();
            // the head's camera looks along the snake, at the world ahead of it
            Gui.screenshot(camera.shell(), "camera-" + world + ".png");
            // and sees it: drawn without the world's solids and objects, the picture changes
            // (the slot machine's front, 1.6 cm from the head's lens, once vanished behind a 2 cm near plane)
            SimSnapshot bare = new SimSnapshot(s.time(), s.bodies(), s.contacts(), s.centerOfMass(), s.measuredAngles(),
                    s.targetAngles(), s.limpModules());
            double seen = differing(render(camera.view(), s), render(camera.view(), bare));
            System.out.printf("camera %s: %.3f of the picture is the world%n", world, seen);
            assertTrue(seen > MIN_WORLD_IN_CAMERA, "the camera in " + world + " hardly sees the world: " + seen);
        } finally {
            camera.shell().dispose();
        }
    }
}
