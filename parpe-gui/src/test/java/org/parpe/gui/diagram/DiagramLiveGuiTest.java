package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.diagram.Ring;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Program;
import org.parpe.core.run.Engine;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.diagram.Projection.View;
import org.parpe.core.run.Breakpoints;
import org.parpe.gui.run.RunController;

/**
 * The live half of the Diagram pane with real widgets on a copy of
 * {@code examples/centipede-walk.xml}, each checked against the same program's engine run
 * headless to the tick the view shows (never against pixels): the gait diagram's "now" column
 * during a run; a breakpoint set on the ring with its button, where the run stops at exactly the
 * tick a module enters the state and goes on with Continue; and a trace recorded by a run
 * scrubbed through the ring, the lanes and the gait diagram. Saves the breakpoint and the
 * scrubbing pictures for docs/ide.md (folder: system property {@code parpe.ideImages}).
 */
class DiagramLiveGuiTest {
    private static IdeWindow ide;
    private static Path centipede;
    private static Path home;

    @BeforeAll
    static void openWindow() throws Exception {
        home = Files.createTempDirectory("parpe-diagram-live-test");
        DiagramWindow.Opened o = DiagramWindow.open(home);
        ide = o.ide();
        centipede = o.copy();
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    private static DiagramPane pane() {
        return IdeAccess.diagram(ide);
    }

    private static void show(View v, String subject) {
        DiagramWindow.show(ide, v, subject);
    }

    /** Each module's instance, state and progress in the same program's engine, run headless to a tick. */
    private record At(int[] inst, int[] state, double[] progress) {
    }

    private static At at(long tick) {
        Engine e = new Engine(pane().program(), RunOptions.defaults());
        e.start();
        while (e.tick() < tick) {
            e.step();
        }
        int n = e.moduleIds().length;
        At a = new At(new int[n], new int[n], new double[n]);
        e.moduleStates(a.inst(), a.state());
        e.moduleProgress(a.progress());
        return a;
    }

    /** Per module, "automaton.state" of the state the engine is in (from the script's model), or null. */
    private static String[] statesAt(long tick) {
        At a = at(tick);
        Program p = pane().program();
        List<Instance> walk = p.behavior("walk").orElseThrow().instances();
        String[] out = new String[a.inst().length];
        for (int m = 0; m < out.length; m++) {
            if (a.inst()[m] >= 0) {
                String name = walk.get(a.inst()[m]).name();
                out[m] = name + "." + p.automaton(name).orElseThrow().states().get(a.state()[m]).name();
            }
        }
        return out;
    }

    /** Whether module {@code m} is a lift at {@code a}: instances 2 and 3 of walk run step. */
    private static boolean lift(At a, int m) {
        return a.inst()[m] == 2 || a.inst()[m] == 3;
    }

    /** Modules per state of "step" (the lifts) at {@code tick}. */
    private static int[] stepCountsAt(long tick) {
        At a = at(tick);
        int[] counts = new int[3];
        for (int m = 0; m < a.inst().length; m++) {
            if (lift(a, m)) {
                counts[a.state()[m]]++;
            }
        }
        return counts;
    }

    /** Per module, how far a lift is through its state at {@code tick}, else −1. */
    private static String stepProgressAt(long tick) {
        At a = at(tick);
        double[] out = a.progress().clone();
        for (int m = 0; m < out.length; m++) {
            if (!lift(a, m)) {
                out[m] = -1;
            }
        }
        return Arrays.toString(out);
    }

    private static Button button(String text) {
        List<Control> all = new ArrayList<>();
        collect((Composite) pane().control(), all);
        return all.stream().filter(c -> c instanceof Button b && b.getText().equals(text)).map(c -> (Button) c).findFirst()
                .orElseThrow(() -> new AssertionError("no button '" + text + "' in the Diagram pane"));
    }

    private static void collect(Composite c, List<Control> out) {
        for (Control k : c.getChildren()) {
            out.add(k);
            if (k instanceof Composite cc) {
                collect(cc, out);
            }
        }
    }

    private static void press(Button b) {
        assertTrue(b.isEnabled(), "'" + b.getText() + "' is enabled");
        b.notifyListeners(SWT.Selection, new Event());
    }

    private static void picture(String name) throws Exception {
        DiagramWindow.picture(ide, name);
    }

    @Test
    void theGaitDiagramShowsEachModulesStateDuringARun() throws Exception {
        show(View.GAIT, null);
        DiagramWindow.tenFrames(ide, () -> pane().live().labels() != null, tick -> {
            String[] expected = statesAt(tick);
            assertEquals(28, Arrays.stream(expected).filter(s -> s != null).count(), "the 28 leg modules are driven");
            assertEquals(Arrays.toString(expected), Arrays.toString(pane().live().labels()), "each module's state at tick " + tick);
        }, null);
    }

    /** The ticks at which a lift module enters state {@code s} of step, in order, up to {@code count} of them. */
    private static List<Long> entries(int s, int count) {
        Engine e = new Engine(pane().program(), RunOptions.defaults());
        int n = e.moduleIds().length;
        int[] inst = new int[n];
        int[] state = new int[n];
        int[] before = new int[n];
        Arrays.fill(before, -1);
        List<Long> out = new ArrayList<>();
        e.start();
        while (out.size() < count) {
            e.step();
            e.moduleStates(inst, state);
            for (int m = 0; m < n; m++) {
                boolean lift = inst[m] == 2 || inst[m] == 3;
                if (lift && state[m] == s && before[m] != s) {
                    out.add(e.tick());
                    break;
                }
            }
            for (int m = 0; m < n; m++) {
                before[m] = inst[m] == 2 || inst[m] == 3 ? state[m] : -1;
            }
        }
        return out;
    }

    @Test
    void aBreakpointOnTheRingStopsTheRunWhereAModuleEntersTheState() throws Exception {
        show(View.RING, "step");
        Ring.Arc lower = pane().shown().ring().arcs().get(1);
        assertEquals("lower", lower.state());
        Point at = pane().where(lower.pos());
        assertNotNull(at, "the arc of lower is drawn");
        Event click = new Event();
        click.button = 1;
        click.x = at.x;
        click.y = at.y;
        pane().canvas().notifyListeners(SWT.MouseDown, click);
        assertEquals(lower.pos(), pane().selected());
        assertTrue(!button("Break on exit").isEnabled(), "lower has no exit condition");
        press(button("Break on entry"));
        RunController c = IdeAccess.controller(ide);
        assertEquals(java.util.Set.of(new Breakpoints.Point("step", 1, Breakpoints.Kind.ENTER)), c.breakpoints().points());
        List<Long> expected = entries(1, 3);
        AtomicReference<RunOutcome> end = new AtomicReference<>();
        IdeAccess.run(ide, org.parpe.gui.run.RunOn.SIMULATOR, 600, end::set);
        try {
            for (int hit = 0; hit < 2; hit++) {
                long tick = expected.get(hit);
                IdeAccess.pump(() -> c.breakpoints().hit() != null && pane().liveLine().startsWith("Paused")
                        && pane().liveTick() == tick || end.get() != null, "the run to stop at tick " + tick);
                assertEquals(null, end.get(), "the run ended early");
                assertTrue(c.paused(), "the run is paused");
                assertEquals(tick, c.breakpoints().hit().tick());
                assertEquals(tick, c.engine().tick(), "the engine stopped at the tick a lift entered lower");
                Thread.sleep(150);
                IdeAccess.settle();
                assertEquals(tick, c.engine().tick(), "no tick runs while paused at the breakpoint");
                assertEquals(Arrays.toString(stepCountsAt(tick)), Arrays.toString(pane().live().counts()),
                        "the ring shows the states at the tick it stopped");
                assertEquals(stepProgressAt(tick), Arrays.toString(pane().live().progress()),
                        "the ring's dots show each lift's progress at the tick it stopped");
                assertTrue(pane().liveLine().contains("entered step.lower at tick " + tick), pane().liveLine());
                if (hit == 1) {
                    // the first stop is at tick 0 (a lift starts in lower); the pictures show the second
                    picture("diagram-breakpoint.png");
                    DiagramWindow.canvasHasHalfTheTab(ide);
                    // the same stop on the gait diagram: its "now" column at that tick
                    show(View.GAIT, null);
                    IdeAccess.pump(() -> pane().live().labels() != null && pane().liveTick() == tick, "the gait overlay at the stop");
                    assertEquals(Arrays.toString(statesAt(tick)), Arrays.toString(pane().live().labels()));
                    picture("diagram-live-gait.png");
                    show(View.RING, "step");
                    IdeAccess.pump(() -> pane().live().counts() != null && pane().liveTick() == tick, "the ring overlay again");
                }
                press(button("Continue"));
                IdeAccess.pump(() -> c.breakpoints().hit() == null, "the run to go on");
            }
            // stopped while paused at the third: the breakpoint is no longer shown as hit
            IdeAccess.pump(() -> c.breakpoints().hit() != null || end.get() != null, "the third stop");
            assertEquals(expected.get(2), c.breakpoints().hit().tick());
        } finally {
            IdeAccess.endRun(ide);
        }
        assertEquals(null, c.breakpoints().hit(), "a stopped run is no longer at its breakpoint");
        IdeAccess.pump(() -> !pane().liveLine().startsWith("Paused"), "the line to forget the breakpoint");
        Point again = pane().where(lower.pos());
        click.x = again.x;
        click.y = again.y;
        pane().canvas().notifyListeners(SWT.MouseDown, click);
        press(button("Clear entry break"));
        assertEquals(java.util.Set.of(), c.breakpoints().points(), "the button clears the breakpoint");
    }

    @Test
    void aRecordedTraceIsScrubbedThroughTheViews() throws Exception {
        // a trace as `parpe run --trace` writes it, of 3 s of this program
        StringWriter csv = new StringWriter();
        Run.Builder b = Run.builder(pane().program(), RunOptions.defaults(), d -> { });
        b.trace(csv);
        b.duration(3);
        b.build().execute();
        Path trace = home.resolve("walk.csv");
        Files.writeString(trace, csv.toString());
        show(View.RING, "step");
        pane().scrub(trace);
        try {
            assertTrue(pane().liveLine().startsWith("walk.csv: t = 0 s (tick 0 of 300)"), pane().liveLine());
            for (int k : new int[] {0, 37, 150, 233, 300}) {
                pane().scrubTo(k);
                assertEquals(k, pane().liveTick());
                assertEquals(Arrays.toString(stepCountsAt(k)), Arrays.toString(pane().live().counts()), "the ring at tick " + k);
                assertEquals(stepProgressAt(k), Arrays.toString(pane().live().progress()), "the ring's progress dots at tick " + k);
            }
            show(View.GAIT, null);
            for (int k : new int[] {0, 80, 299}) {
                pane().scrubTo(k);
                assertEquals(Arrays.toString(statesAt(k)), Arrays.toString(pane().live().labels()), "the gait diagram at tick " + k);
            }
            pane().scrubTo(120);
            assertTrue(pane().liveLine().startsWith("walk.csv: t = 1.2 s (tick 120 of 300)"), pane().liveLine());
            picture("diagram-scrub.png");
        } finally {
            press(button("Close trace"));
        }
        assertEquals(null, pane().live().labels(), "no overlay once the trace is closed");
    }

    @Test
    void aTraceOfAnotherScriptIsRefusedWithItsFileAndLine() throws Exception {
        Path other = home.resolve("snake.csv");
        Files.writeString(other, "time,m0,m99\n0.000000,0.000000,0.000000\n");
        show(View.RING, "step");
        pane().scrub(other);
        assertTrue(pane().liveLine().startsWith(other + ":1:1: the trace has module 99, which the script does not have"),
                pane().liveLine());
        assertEquals(null, pane().live().counts());
    }

    @Test
    void aStateWithAnExitConditionTakesABreakpointOnItsExit() throws Exception {
        Path sensors = home.resolve("scripts").resolve("sensor-exit.xml");
        Files.copy(Path.of(System.getProperty("parpe.examples", "../examples"), "sensor-exit.xml"), sensors);
        IdeAccess.open(ide, sensors);
        try {
            IdeAccess.pump(() -> pane().current() && pane().program() != null, "the sensor-exit script");
            show(View.RING, "inch");
            Ring.Arc press = pane().shown().ring().arcs().get(2);
            assertEquals("press", press.state());
            Point at = pane().where(press.pos());
            Event click = new Event();
            click.button = 1;
            click.x = at.x;
            click.y = at.y;
            pane().canvas().notifyListeners(SWT.MouseDown, click);
            press(button("Break on exit"));
            RunController c = IdeAccess.controller(ide);
            assertEquals(java.util.Set.of(new Breakpoints.Point("inch", 2, Breakpoints.Kind.EXIT)), c.breakpoints().points());
            press(button("Clear exit break"));
            assertEquals(java.util.Set.of(), c.breakpoints().points());
            // a state without an exit condition has no such breakpoint
            Point reach = pane().where(pane().shown().ring().arcs().get(1).pos());
            click.x = reach.x;
            click.y = reach.y;
            pane().canvas().notifyListeners(SWT.MouseDown, click);
            assertTrue(!button("Break on exit").isEnabled(), "reach has no exit condition");
        } finally {
            IdeAccess.open(ide, centipede);
            IdeAccess.pump(() -> pane().current() && IdeAccess.program(ide) != null
                    && IdeAccess.program(ide).behavior("walk").isPresent(), "the centipede again");
        }
    }
}
