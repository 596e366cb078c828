package org.parpe.gui.pose;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.eclipse.jface.text.ITextOperationTarget;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Scale;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.TestInfo;
import org.junit.jupiter.api.Test;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.run.RunOn;
import org.parpe.gui.view3d.View3D;
import org.parpe.serial.record.RecordingWriter;

/**
 * The Pose panel for real on an X display: pose three poses of a centipede's front pair of legs
 * with the sliders and by dragging a module in the 3D view, edit the list, play it in the
 * simulator, save it, reopen the recording and run it (the trace goes through the poses), and
 * write it into a script for two other pairs (the trace shows the phase delay; one Undo takes it
 * back). Widgets are driven with the events a user's clicks send; every wait is bounded. Each
 * test poses its own copy of the script (poses stay with their script), so that none depends
 * on another's order or poses (issue 32, item 6).
 */
class PosePanelGuiTest {
    static final String PAIRS = """
            <?xml version="1.0"?>
            <!-- the simulator's centipede: pairs of legs (left swing, left lift, right swing, right lift) -->
            <program>
              <robot>
                <structure>
                  <front elements="0, 1, 14, 15"/>
                  <pair1 elements="2, 3, 16, 17"/>
                  <pair2 elements="4, 5, 18, 19"/>
                  <leftFront elements="0, 1"/>
                  <rightFront elements="14, 15"/>
                  <rest elements="6..13, 20..54"/>
                </structure>
              </robot>
            </program>
            """;
    private static IdeWindow ide;
    private static Path dir;
    private static PosePanel panel;
    /** This test's own copy of the script, in a folder of its own: its poses are this test's. */
    private Path script;

    @BeforeAll
    static void openWindow() throws Exception {
        dir = Files.createTempDirectory("parpe-pose-test");
        ide = IdeAccess.openIde(dir.resolve("home"));
    }

    @BeforeEach
    void poseTheFrontPairOfAFreshScript(TestInfo test) throws Exception {
        Path own = Files.createDirectories(dir.resolve(test.getTestMethod().orElseThrow().getName()));
        script = own.resolve("pairs-centipede.xml");
        Files.writeString(script, PAIRS);
        openScript(script);
        IdeAccess.showPosePanel(ide);
        panel = IdeAccess.pose(ide);
        panel.pollNow();
        panel.chooseGroup("front");
        IdeAccess.pump(() -> panel.posingReady() && panel.poses() != null && "front".equals(panel.poses().group()),
                "the posed centipede to be built");
    }

    /** The three poses of the first test, by the sliders: what playing, saving and using start from. */
    private static void captureThreePoses() {
        double[][] poses = {{-25, 20, -25, -60}, {-25, -60, -25, -60}, {25, -60, 25, 20}};
        for (int i = 0; i < poses.length; i++) {
            slide(0, (int) poses[i][0]);
            slide(1, (int) poses[i][1]);
            slide(14, (int) poses[i][2]);
            slide(15, (int) poses[i][3]);
            if (i == 1) {
                panel.table().timeBox().setText("0.5");
            }
            press("Capture");
        }
        assertEquals(3, panel.poses().size());
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    private static void openScript(Path file) {
        int before = IdeAccess.validations(ide);
        IdeAccess.open(ide, file);
        IdeAccess.pump(() -> IdeAccess.validations(ide) > before && IdeAccess.program(ide) != null
                && IdeAccess.program(ide).file().endsWith(file.getFileName().toString()), file.getFileName() + " to load");
        assertEquals(0, IdeAccess.problems(ide).errorCount(), "errors: " + IdeAccess.problems(ide).shown());
        panel = IdeAccess.pose(ide);
        if (panel != null) {
            panel.pollNow();
        }
    }

    private static void press(String button) {
        Button b = panel.button(button);
        assertNotNull(b, "no button " + button);
        b.notifyListeners(SWT.Selection, new Event());
    }

    private static void slide(int module, int degrees) {
        Scale s = panel.sliders().scale(module);
        assertNotNull(s, "no slider for module " + module);
        s.setSelection(degrees + 90);
        s.notifyListeners(SWT.Selection, new Event());
    }

    private static void mouse(int type, int x, int y, int button) {
        mouse(type, x, y, button, 0);
    }

    private static void mouse(int type, int x, int y, int button, int stateMask) {
        Event e = new Event();
        e.stateMask = stateMask;
        e.x = x;
        e.y = y;
        e.button = button;
        IdeAccess.view(ide).control().notifyListeners(type, e);
    }

    /** A module of the group whose picture is under its own screen point (not hidden by another). */
    private static int grabbable(View3D view, int... ids) {
        for (int id : ids) {
            Point p = view.screenPoint(id);
            if (p != null && view.moduleAt(p.x, p.y) == id) {
                return id;
            }
        }
        return -1;
    }

    @Test
    void posesThreePosesWithSlidersAndDraggingAndEditsTheList() throws Exception {
        assertEquals("front", panel.poses().group());
        slide(0, -25);
        slide(1, 20);
        slide(14, -25);
        slide(15, -60);
        press("Capture");

        IdeAccess.pump(() -> IdeAccess.view(ide).lastSnapshot() != null
                && Math.abs(IdeAccess.view(ide).lastSnapshot().angle(15) + 60) < 5, "the simulated leg to follow the sliders");
        View3D view = IdeAccess.view(ide);
        view.focus(panel.posedModules());
        IdeAccess.settle();
        int id = grabbable(view, 1, 15, 0, 14);
        assertTrue(id >= 0, "no module of the front pair can be grabbed in the 3D view");
        double before = panel.sliders().angle(id);
        Point p = view.screenPoint(id);
        mouse(SWT.MouseDown, p.x, p.y, 1);
        mouse(SWT.MouseMove, p.x, p.y - 20, 0);
        mouse(SWT.MouseMove, p.x, p.y - 40, 0);
        mouse(SWT.MouseUp, p.x, p.y - 40, 1);
        assertEquals(before + 40 * View3D.DEGREES_PER_PIXEL, panel.sliders().angle(id), 1e-9,
                "dragging module " + id + " up by 40 pixels should turn its joint");
        slide(0, -25);
        slide(1, -60);
        slide(14, -25);
        slide(15, -60);
        double[] second = panel.sliders().angles();
        panel.table().timeBox().setText("0.5");
        press("Capture");
        slide(0, 25);
        slide(1, -60);
        slide(14, 25);
        slide(15, 20);
        press("Capture");
        assertEquals(3, panel.poses().size());
        assertArrayEquals(second, panel.poses().get(1).angles());
        assertEquals(0.5, panel.poses().get(1).interval());
        assertEquals(3, panel.table().table().getItemCount(), "the list shows every pose");

        // Duplicate the last pose, mirror the copy (the front pair swaps left and right), delete it.
        panel.table().select(2);
        press("Duplicate");
        assertEquals(4, panel.poses().size());
        press("Mirror");
        assertArrayEquals(new double[] {25, 20, 25, -60}, panel.poses().get(3).angles());
        press("Delete");
        assertEquals(3, panel.poses().size());
        // Retime the second pose; the first cannot move up, the second moves down and back.
        panel.table().select(1);
        panel.table().timeBox().setText("0.8");
        press("Set time");
        assertEquals(0.8, panel.poses().get(1).interval());
        press("Down");
        assertArrayEquals(second, panel.poses().get(2).angles());
        press("Up");
        assertArrayEquals(second, panel.poses().get(1).angles());
        assertTrue(panel.table().table().getItem(1).getText(1).equals("0.80"), "the list shows the new time");
        assertTrue(panel.unsaved().contains("3 poses of front in pairs-centipede.xml"),
                "closing the window would ask before losing them: " + panel.unsaved());
        IdeAccess.screenshot(IdeAccess.shell(ide), "pose-panel-posed.png");
    }

    @Test
    void playsThePosesInTheSimulatorAtTwiceTheRate() {
        captureThreePoses();
        panel.output().choose(2, false, RunOn.SIMULATOR);
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        assertTrue(panel.output().play(outcome::set), "playback did not start: " + IdeAccess.status(ide));
        IdeAccess.pump(() -> outcome.get() != null, "the playback to end");
        assertEquals(RunOutcome.Status.COMPLETED, outcome.get().status(), outcome.get().message());
        double cycle = 0;
        for (double t : RecordingWriter.rowTimes(panel.poses().toRecording())) {
            cycle += t;
        }
        // The entry ends at the tick after the last pose is reached (PARSL.md §8), and the scaled
        // state durations need not fall on ticks: allow two ticks.
        assertEquals(cycle / 2, outcome.get().time(), 0.021, "once through the poses at x2 takes half the recorded time");
        IdeAccess.pump(() -> !IdeAccess.running(ide), "the run to wind up");
    }

    @Test
    void savesTheRecordingAndTheReopenedFileRunsThroughThePoses() throws Exception {
        captureThreePoses();
        List<PoseList.Pose> poses = panel.poses().poses();
        double[] times = RecordingWriter.rowTimes(panel.poses().toRecording());
        Path saved = script.resolveSibling("front-poses.xml");
        List<String> unsavedBefore = panel.unsaved();
        assertTrue(panel.output().save(saved), IdeAccess.status(ide));
        assertEquals(unsavedBefore.size() - 1, panel.unsaved().size(), "saved poses are kept: " + panel.unsaved());
        openScript(saved);
        Traces trace = Traces.run(IdeAccess.program(ide), 10);
        int[] modules = {0, 1, 14, 15};
        double reached = 0;
        for (int i = 0; i < poses.size(); i++) {
            reached += times[i];
            double when = Math.round(reached * 100) / 100.0;
            for (int k = 0; k < modules.length; k++) {
                assertEquals(poses.get(i).angles()[k], trace.at(modules[k], when), 0.005,
                        "module " + modules[k] + " at pose " + (i + 1) + " (t = " + when + ")");
            }
        }
        int had = panel.poses().size();
        press("From script");
        assertEquals(had + poses.size(), panel.poses().size(), "From script adds the recording's poses");
        for (int i = 0; i < poses.size(); i++) {
            assertArrayEquals(poses.get(i).angles(), panel.poses().get(had + i).angles(), 1e-9);
        }
        // Issue 18 item 4: "Save recording..." over the script open in the editor (or a link to it)
        // replaced it on disk behind the editor's back; it is refused and the script stays.
        String open = Files.readString(saved);
        Path link = Files.createSymbolicLink(script.resolveSibling("link-to-open.xml"), saved);
        for (Path over : List.of(saved, link)) {
            assertFalse(panel.output().save(over), "saved over the open script through " + over);
            assertTrue(IdeAccess.status(ide).contains("it is the script open in the editor"), IdeAccess.status(ide));
        }
        assertEquals(open, Files.readString(saved));
    }

    /**
     * Fills in the "Use on another group" dialog as a user would: a period of 0 first (refused,
     * the dialog stays open and says why), then pair1 and pair2, period 2, phase 0, offset 0.25.
     */
    private static void fillUseDialog(List<String> seen) {
        org.eclipse.swt.widgets.Shell dialog = null;
        for (org.eclipse.swt.widgets.Shell sh : IdeAccess.shell(ide).getShells()) {
            if (!sh.isDisposed() && sh.getText().equals("Use the poses on other groups")) {
                dialog = sh;
            }
        }
        if (dialog == null) {
            IdeAccess.shell(ide).getDisplay().timerExec(200, () -> fillUseDialog(seen));
            return;
        }
        org.eclipse.swt.widgets.List groups = null;
        List<org.eclipse.swt.widgets.Text> fields = new java.util.ArrayList<>();
        org.eclipse.swt.widgets.Label problem = null;
        for (org.eclipse.swt.widgets.Control c : all(dialog)) {
            if (c instanceof org.eclipse.swt.widgets.List l) {
                groups = l;
            } else if (c instanceof org.eclipse.swt.widgets.Text t) {
                fields.add(t);
            } else if (c instanceof org.eclipse.swt.widgets.Label l) {
                problem = l;
            }
        }
        Button ok = PoseTable.find(dialog, "Write into script");
        if (groups == null || fields.size() != 3 || problem == null || ok == null) {
            seen.add("unexpected dialog");
            dialog.close();
            return;
        }
        seen.add(String.join(",", groups.getItems()));
        groups.setSelection(new String[] {"pair1"});
        fields.get(0).setText("0");
        ok.notifyListeners(SWT.Selection, new Event());
        seen.add(dialog.isDisposed() ? "written with period 0" : "refused: " + problem.getText());
        fields.get(0).setText("2");
        fields.get(1).setText("0");
        fields.get(2).setText("0.25");
        groups.setSelection(new String[] {"pair1", "pair2"});
        ok.notifyListeners(SWT.Selection, new Event());
        seen.add(dialog.isDisposed() ? "written" : "still open: " + problem.getText());
    }

    private static List<org.eclipse.swt.widgets.Control> all(org.eclipse.swt.widgets.Composite parent) {
        List<org.eclipse.swt.widgets.Control> out = new java.util.ArrayList<>();
        for (org.eclipse.swt.widgets.Control c : parent.getChildren()) {
            out.add(c);
            if (c instanceof org.eclipse.swt.widgets.Composite k) {
                out.addAll(all(k));
            }
        }
        return out;
    }

    private static void closeDialogs() {
        if (IdeAccess.shell(ide).isDisposed()) {
            return; // the timer outlived this class's window (a test that ended before it fired)
        }
        for (org.eclipse.swt.widgets.Shell sh : IdeAccess.shell(ide).getShells()) {
            if (!sh.isDisposed()) {
                sh.close();
            }
        }
    }

    @Test
    void usedOnTwoOtherPairsTheScriptRunsThemWithThePhaseDelayAndOneUndoTakesItBack() throws Exception {
        captureThreePoses();
        PoseList recorded = panel.poses();
        String before = IdeAccess.editor(ide).document().get();
        assertNotNull(recorded);
        // The dialog is modal: fill it in from a timer while the button's nested event loop runs.
        List<String> seen = new java.util.ArrayList<>();
        IdeAccess.shell(ide).getDisplay().timerExec(300, () -> fillUseDialog(seen));
        IdeAccess.shell(ide).getDisplay().timerExec(25_000, PosePanelGuiTest::closeDialogs);
        press("Use on another group\u2026");
        assertEquals(List.of("front,pair1,pair2", "refused: The period must be a number of seconds > 0, got 0.0.", "written"),
                seen, "the dialog offers the groups of four modules, refuses a period of 0, then writes");
        assertNotEquals(before, IdeAccess.editor(ide).document().get());
        int v = IdeAccess.validations(ide);
        IdeAccess.pump(() -> IdeAccess.validations(ide) > v && IdeAccess.program(ide) != null && IdeAccess.program(ide).behavior("play_front").isPresent()
                && IdeAccess.program(ide).automaton("rec_front").isPresent(),
                "the changed script to load");
        assertEquals(0, IdeAccess.problems(ide).errorCount(), "errors: " + IdeAccess.problems(ide).shown());
        Traces trace = Traces.run(IdeAccess.program(ide), 6);
        // pair2 lags pair1 by 0.25 of a 2 s cycle: it is where pair1 was 0.5 s earlier.
        boolean moved = false;
        for (double t = 2.0; t <= 5.5; t += 0.13) {
            double now = Math.round(t * 100) / 100.0;
            assertEquals(trace.at(2, now - 0.5), trace.at(4, now), 1e-6, "swing of pair2 at " + now);
            assertEquals(trace.at(3, now - 0.5), trace.at(5, now), 1e-6, "lift of pair2 at " + now);
            moved |= trace.at(2, now) != trace.at(4, now);
        }
        assertTrue(moved, "the two pairs move in step");
        IdeAccess.screenshot(IdeAccess.shell(ide), "pose-panel-used-on-pairs.png");
        IdeAccess.editor(ide).run(ITextOperationTarget.UNDO);
        assertEquals(before, IdeAccess.editor(ide).document().get(), "one Undo should take the whole change back");
    }

    @Test
    void ctrlClickInThe3DViewPicksModulesToPose() {
        View3D view = IdeAccess.view(ide);
        IdeAccess.pump(() -> panel.posingReady(), "the posed robot");
        IdeAccess.settle();
        int id = grabbable(view, 4, 5, 18, 19, 2, 3);
        assertTrue(id >= 0, "no module of pair1 or pair2 under its own screen point");
        Point p = view.screenPoint(id);
        mouse(SWT.MouseDown, p.x, p.y, 1, SWT.MOD1);
        mouse(SWT.MouseUp, p.x, p.y, 1, SWT.MOD1);
        assertEquals(PosePanel.PICKED, panel.poses().group());
        assertArrayEquals(new int[] {id}, panel.poses().modules());
        assertNotNull(panel.sliders().scale(id), "a slider for the picked module");
    }

    /** The documented {@code ./parpe gui examples/tutorial/01-recorded-leg-centipede.xml --pose-panel --screenshot …}. */
    @Test
    void posePanelOptionShowsTheRecordedLegsPoses() throws Exception {
        Path example = Path.of(System.getProperty("parpe.examples", "../examples"), "tutorial", "01-recorded-leg-centipede.xml");
        assertTrue(Files.isRegularFile(example), "no " + example);
        openScript(example);
        Path shot = Path.of(System.getProperty("parpe.artefacts", "target/gui-test-artefacts"), "pose-panel-option.png");
        Files.createDirectories(shot.getParent());
        Files.deleteIfExists(shot);
        org.parpe.gui.automation.Automation.start(ide.automated(), new org.parpe.gui.automation.LaunchOptions(example, -1, shot, false, false, true, null, false));
        IdeAccess.pump(() -> Files.exists(shot), "the --pose-panel screenshot");
        assertEquals("front", panel.poses().group());
        // The earlier tests' poses of front stay; the recording's four are added after them and selected.
        List<PoseList.Pose> all = panel.poses().poses();
        assertTrue(all.size() >= 4, "the recording's four poses in the list");
        List<PoseList.Pose> poses = all.subList(all.size() - 4, all.size());
        assertArrayEquals(new double[] {-25, 20, -25, -60}, poses.get(0).angles());
        assertArrayEquals(new double[] {25, -60, 25, 20}, poses.get(2).angles());
        assertEquals(all.size() - 4, panel.table().selection(), "the first added pose is selected");
        assertTrue(panel.posingReady());
        assertEquals(-60, IdeAccess.view(ide).lastSnapshot().angle(15), 6, "the posed robot stands in the first pose");
    }

    /**
     * Issue 23, item 10: poses captured for one script followed into the next file opened, and
     * quitting asked twice ("Unsaved changes", then the poses). Each script keeps its own poses;
     * quitting asks one question that names both.
     */
    @Test
    void posesStayWithTheirScriptAndQuittingAsksOnce() throws Exception {
        Path first = script.resolveSibling("first-centipede.xml");
        Files.writeString(first, PAIRS);
        openScript(first);
        panel.chooseGroup("front");
        IdeAccess.pump(() -> panel.posingReady() && panel.poses() != null && "front".equals(panel.poses().group()), "front to pose");
        assertEquals(0, panel.poses().size(), "a script opened for the first time has no poses yet");
        slide(0, -20);
        press("Capture");
        press("Capture");
        assertEquals(2, panel.poses().size());
        List<String> lost = panel.unsaved();
        assertTrue(lost.contains("2 poses of front in first-centipede.xml"), lost.toString());

        Path second = script.resolveSibling("second-centipede.xml");
        Files.writeString(second, PAIRS);
        openScript(second);
        panel.chooseGroup("front");
        IdeAccess.pump(() -> panel.posingReady() && panel.poses() != null, "front of the second script to pose");
        assertEquals(0, panel.poses().size(), "the poses of first-centipede.xml followed into second-centipede.xml");
        assertEquals(lost, panel.unsaved(), "the first script's poses are still its own");

        openScript(first);
        panel.chooseGroup("front");
        IdeAccess.pump(() -> panel.posingReady() && panel.poses() != null, "front of the first script again");
        assertEquals(2, panel.poses().size(), "the first script's poses are back with it");

        IdeAccess.editor(ide).document().replace(0, 0, "<!-- edited -->\n");
        List<String> asked = new java.util.ArrayList<>();
        assertTrue(IdeAccess.closeRequested(ide, asked, message -> 1), "Don't Save closes");
        assertEquals(1, asked.size(), "one question before quitting: " + asked);
        assertTrue(asked.get(0).contains("first-centipede.xml has unsaved changes")
                && asked.get(0).contains("2 poses of front in first-centipede.xml"), asked.get(0));
        IdeAccess.editor(ide).document().replace(0, "<!-- edited -->\n".length(), "");
    }

    /**
     * Issue 23, item 5: nothing told whether a drag would bend a joint or orbit, and the wheel
     * zoomed on the body's centre rather than the group being posed.
     */
    @Test
    void hoverSaysWhatADragDoesAndTheWheelZoomsOnTheGroup() throws Exception {
        View3D view = IdeAccess.view(ide);
        view.focus(panel.posedModules());
        IdeAccess.settle();
        int id = grabbable(view, 1, 15, 0, 14);
        assertTrue(id >= 0, "no module of the front pair can be grabbed in the 3D view");
        Point p = view.screenPoint(id);
        mouse(SWT.MouseMove, p.x, p.y, 0);
        assertEquals(id, view.hovered(), "the module under the mouse is lit");
        assertEquals("Drag up or down: bend the joint of m" + id, view.dragHint());
        IdeAccess.screenshot(IdeAccess.shell(ide), "pose-panel-hover.png");
        mouse(SWT.MouseMove, 3, view.control().getSize().y - 3, 0);
        assertEquals(-1, view.hovered());
        assertEquals("Drag: turn the view around", view.dragHint());

        // Frame the whole robot, then one notch of the wheel: the view turns to the posed group.
        view.resetView();
        IdeAccess.settle();
        java.util.Set<Integer> group = view.highlighted().get();
        assertTrue(!group.isEmpty(), "the posed group is highlighted");
        double x = 0, y = 0, z = 0;
        int n = 0;
        for (org.parpe.sim.snapshot.SimBody b : view.lastSnapshot().bodies()) {
            if (group.contains(b.moduleId())) {
                x += b.position().x();
                y += b.position().y();
                z += b.position().z();
                n++;
            }
        }
        Event wheel = new Event();
        wheel.count = 3;
        view.control().notifyListeners(SWT.MouseVerticalWheel, wheel);
        double[] t = view.target();
        assertEquals(x / n, t[0], 0.02, "the wheel zooms on the group, not the body");
        assertEquals(y / n, t[1], 0.02);
    }
}
