package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Breakpoints;
import org.parpe.core.run.Engine;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.WallClockPacer;
import org.parpe.core.run.Breakpoints.Kind;
import org.parpe.core.run.Breakpoints.Point;

/**
 * Breakpoints through the engine: a real {@link Run} (paced by the IDE's {@link WallClockPacer}, paused as the IDE pauses it,
 * as fast as it goes) stops at exactly the tick a module enters a state or a state's exit
 * condition becomes true, stays there (no further tick) until Continue, and goes on to the next.
 * The ticks are worked out by hand from the script (PARSL.md §7.1: a transition due at exactly
 * a tick happens at that tick; an exit condition is looked at first when a module advances).
 */
class BreakpointsTest {
    /*
     * Two modules, two states of 1 s each (period 2). Module 1 is half a cycle behind module 0,
     * so it starts (tick 0) in "down"; down's exit condition "$time > 0.735" is first true at
     * tick 74 (t = 0.74), where module 1 leaves down for up. Module 0 enters down by time at
     * t = 1 s (tick 100) and leaves it at once by the exit condition at tick 101.
     */
    private static final String SCRIPT = """
            <?xml version="1.0" ?>
            <program>
              <robot><structure><pair elements="0, 1"/></structure></robot>
              <main><swing/></main>
              <behaviors><swing><updown group="pair" phase="0.5" period="2"/></swing></behaviors>
              <automata><updown states="up, down" times="1, 1[$time &gt; 0.735]"/></automata>
              <states><up angles="30"/><down angles="-30"/></states>
            </program>
            """;

    private record Stop(long engineTick, Breakpoints.Hit hit) {
    }

    /** Runs the script with {@code set} breakpoints and the duration given, continuing at each stop. */
    private static List<Stop> stops(Breakpoints bp, double seconds) throws Exception {
        var loaded = ScriptLoader.loadText(Path.of("bp.xml"), SCRIPT, Map.of());
        assertNotNull(loaded.program(), loaded.diagnostics().toString());
        Run.Builder b = Run.builder(loaded.program(), RunOptions.defaults(), d -> { });
        Engine e = b.engine();
        WallClockPacer pacer = new WallClockPacer(Double.POSITIVE_INFINITY);
        b.pacer(pacer);
        b.duration(seconds);
        b.observer(bp.watch(e, () -> pacer.setPaused(true)));
        Run run = b.build();
        AtomicReference<RunOutcome> end = new AtomicReference<>();
        Thread t = new Thread(() -> end.set(run.execute()), "bp-test-engine");
        t.setDaemon(true);
        t.start();
        List<Stop> out = new ArrayList<>();
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (t.isAlive()) {
            assertTrue(System.nanoTime() < deadline, "the run neither ends nor stops");
            if (pacer.paused()) {
                long at = e.tick();
                Thread.sleep(30);
                assertEquals(at, e.tick(), "no tick runs while stopped at a breakpoint");
                out.add(new Stop(at, bp.hit()));
                bp.clearHit();
                pacer.setPaused(false);
            }
            Thread.sleep(1);
        }
        assertEquals(RunOutcome.Status.COMPLETED, end.get().status(), String.valueOf(end.get()));
        return out;
    }

    @Test
    void theRunStopsAtTheTickAStateIsEntered() throws Exception {
        Breakpoints bp = new Breakpoints();
        bp.toggle(new Point("updown", 1, Kind.ENTER));
        List<Stop> s = stops(bp, 1.95);
        // module 1 starts in down (tick 0), module 0 enters it at 1 s, module 1 again after a whole second in up (ticks 74–173: up got its first 0.01 s at tick 74)
        assertEquals(List.of(0L, 100L, 173L), s.stream().map(Stop::engineTick).toList());
        assertEquals(List.of(1, 0, 1), s.stream().map(x -> x.hit().moduleId()).toList());
        for (Stop x : s) {
            assertEquals(x.engineTick(), x.hit().tick(), "the hit names the tick the run stopped at");
            assertEquals("down", x.hit().state());
        }
        assertEquals("module 0 entered updown.down at tick 100 (t = 1 s)", s.get(1).hit().describe());
    }

    @Test
    void theRunStopsAtTheTickAnExitConditionBecomesTrue() throws Exception {
        Breakpoints bp = new Breakpoints();
        bp.toggle(new Point("updown", 1, Kind.EXIT));
        List<Stop> s = stops(bp, 1.95);
        assertEquals(List.of(74L, 101L, 174L), s.stream().map(Stop::engineTick).toList());
        assertEquals(List.of(1, 0, 1), s.stream().map(x -> x.hit().moduleId()).toList());
        assertEquals("the exit condition of updown.down became true for module 1 at tick 74 (t = 0.74 s)",
                s.get(0).hit().describe());
    }

    @Test
    void aClearedBreakpointNoLongerStops() throws Exception {
        Breakpoints bp = new Breakpoints();
        Point p = new Point("updown", 0, Kind.ENTER);
        bp.toggle(p);
        assertTrue(bp.has(p));
        bp.toggle(p);
        assertEquals(List.of(), stops(bp, 1.5));
        assertNull(bp.hit());
    }
}
