package org.parpe.gui.view3d;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicReference;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.parpe.gui.app.Gui;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.geom.Vec3;

/**
 * Issue 23, item 5: with TrackRobot the snake's motion was hard to see (no live distance, no
 * trail); with it off a new run started off the screen; Module ID labels on the centipede ran
 * into a blur. A real canvas under Xvfb drawing snapshots made here.
 */
class View3DGuiTest {
    private Shell shell;
    private View3D view;
    private final AtomicReference<SimSnapshot> now = new AtomicReference<>();

    @BeforeEach
    void open() {
        shell = new Shell(Gui.display());
        shell.setLayout(new FillLayout());
        shell.setSize(500, 400);
        view = new View3D(shell);
        view.setSource(now::get);
        shell.open();
    }

    @AfterEach
    void close() {
        shell.dispose();
    }

    /** A snake of {@code n} segments along x from {@code x0}, at time {@code t}. */
    private static SimSnapshot snake(double t, double x0, int n) {
        List<SimBody> bodies = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            bodies.add(new SimBody(i, "base", PartKind.SEGMENT_BASE, new BodyShape.Box(0.02, 0.02, 0.02),
                    new Vec3(x0 + 0.05 * i, 0, 0.02), Mat3.IDENTITY));
        }
        Vec3 com = new Vec3(x0 + 0.05 * (n - 1) / 2, 0, 0.02);
        return new SimSnapshot(t, bodies, List.of(), com, new TreeMap<>(), new TreeMap<>(), new TreeSet<>());
    }

    private void draw(SimSnapshot s) {
        now.set(s);
        Image img = new Image(shell.getDisplay(), 500, 400);
        GC gc = new GC(img);
        try {
            view.render(gc, 500, 400);
        } finally {
            gc.dispose();
            img.dispose();
        }
    }

    @Test
    void trackRobotShowsTheDistanceFromTheStartAndATrailThatANewRunStartsAgain() {
        view.setTrackRobot(true);
        draw(snake(0, 0, 4));
        assertEquals(0, view.distanceFromStart(), 1e-12);
        draw(snake(0.5, 0.1, 4));
        draw(snake(1.0, 0.3, 4));
        assertEquals(0.3, view.distanceFromStart(), 1e-9);
        assertTrue(view.hudText().endsWith("0.30 m from the start"), view.hudText());
        assertEquals(3, view.trailPoints(), "a point of the trail per place the robot was");
        draw(snake(0, 2, 4));
        assertEquals(0, view.distanceFromStart(), 1e-12, "a new run measures from its own start");
        assertEquals(1, view.trailPoints(), "and its trail starts again");
    }

    @Test
    void withoutTrackRobotANewRunIsFramedWhereverItStarts() {
        view.setTrackRobot(false);
        draw(snake(0, 0, 4));
        draw(snake(3, 0.2, 4));
        assertEquals(0.075, view.target()[0], 1e-9, "within a run the view stays where it is");
        draw(snake(0, 5, 4));
        assertEquals(5.075, view.target()[0], 1e-9, "the next run, starting 5 m away, is framed, not off the screen");
    }

    /**
     * Issue 35: a snake curled into a standing loop (lesson 15) was framed on its footprint at
     * floor level, and the top of the loop, where its ends latch, was off the picture.
     */
    @Test
    void aStandingLoopIsFramedWhole() {
        view.setTrackRobot(false);
        List<SimBody> bodies = new ArrayList<>();
        int n = 10;
        for (int i = 0; i < n; i++) {
            double a = 2 * Math.PI * i / n;
            bodies.add(new SimBody(i, "base", PartKind.SEGMENT_BASE, new BodyShape.Box(0.02, 0.02, 0.02),
                    new Vec3(0.1 * Math.sin(a), 0, 0.12 - 0.1 * Math.cos(a)), Mat3.IDENTITY));
        }
        draw(new SimSnapshot(0, bodies, List.of(), new Vec3(0, 0, 0.12), new TreeMap<>(), new TreeMap<>(), new TreeSet<>()));
        view.resetView();
        draw(new SimSnapshot(0.01, bodies, List.of(), new Vec3(0, 0, 0.12), new TreeMap<>(), new TreeMap<>(),
                new TreeSet<>()));
        for (int i = 0; i < n; i++) {
            org.eclipse.swt.graphics.Point p = view.screenPoint(i);
            assertTrue(p != null && p.x >= 0 && p.x < 500 && p.y >= 0 && p.y < 400, "module " + i + " at " + p);
        }
    }

    @Test
    void moduleIdLabelsNeverOverlap() {
        view.setTrackRobot(false);
        view.setShowIds(true);
        // 40 segments 5 cm apart seen from 6 m away: their labels would run into each other.
        draw(snake(0, 0, 40));
        view.resetView();
        draw(snake(0.01, 0, 40));
        List<SceneRenderer.Label> shown = view.renderer().shownLabels();
        assertTrue(!shown.isEmpty() && shown.size() < 40, shown.size() + " labels shown");
        for (int i = 0; i < shown.size(); i++) {
            for (int j = i + 1; j < shown.size(); j++) {
                Rectangle a = shown.get(i).box();
                Rectangle b = shown.get(j).box();
                assertTrue(!a.intersects(b), "labels " + shown.get(i).id() + " and " + shown.get(j).id() + " overlap");
            }
        }
    }

    @Test
    void labelsArePlacedHighlightedAndNearestFirstAndOnlyWhereThereIsRoom() {
        List<SceneRenderer.Label> placed = SceneRenderer.place(List.of(
                new SceneRenderer.Label(7, new Rectangle(0, 0, 20, 10), -1),
                new SceneRenderer.Label(1, new Rectangle(10, 5, 20, 10), 0.5),
                new SceneRenderer.Label(2, new Rectangle(40, 0, 20, 10), 0.6),
                new SceneRenderer.Label(3, new Rectangle(45, 2, 20, 10), 0.7)));
        assertEquals(List.of(7, 2), placed.stream().map(SceneRenderer.Label::id).toList());
    }
}
