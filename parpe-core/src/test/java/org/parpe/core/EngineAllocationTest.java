package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Engine;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.Stimulus;

/** The tick loop does not allocate once the run has started (STYLE.md): bytes, not time. */
class EngineAllocationTest {
    @Test
    void ticksDoNotAllocate() {
        String script = "<program><robot><structure><body elements=\"0..199\"/><legs elements=\"200..209\"/></structure>"
                + "<sensors><touch elements=\"legs\"/><angle elements=\"all\"/><dock elements=\"legs\"/></sensors>"
                + "<actuators><latch elements=\"legs\"/></actuators></robot>"
                + "<controls><dir type=\"radio\" values=\"fwd, back\"/><speed type=\"slider\" min=\"0.1\" max=\"5\" value=\"1\"/></controls>"
                + "<main cycles=\"forever\"><go time=\"3\"/><rest time=\"1\"/></main><behaviors>"
                + "<go><if cond=\"$dir == fwd\"><wave group=\"body\" phase=\"1/$count\" period=\"2/$speed\"/></if>"
                + "<crawl group=\"legs\" phase=\"0.3\" cycles=\"5\"/></go><rest><wave group=\"all\" period=\"0.5\"/></rest></behaviors>"
                + "<automata><wave states=\"crest, trough\"/><crawl states=\"lift, push\" times=\"1, 2[$_self_touch_left == 1]\"/></automata>"
                + "<states><crest angles=\"30*sin(2*pi*$phase) + $_prev_angle/10 + sum(1, 2, $cycle)\" interp=\"smooth\"/>"
                + "<trough angles=\"-30*cos(pi*$index/$count) + if($time &gt; 1, 1, 0)\"/>"
                + "<lift angles=\"40 + $_self_dock_0\" latch=\"0\"/><push angles=\"-20 + rand()\" unlatch=\"0\" latch=\"1\"/></states></program>";
        LoadResult r = ScriptLoader.loadText(Path.of("alloc.xml"), script, Map.of());
        assertTrue(r.ok(), r.diagnostics()::toString);
        Engine e = new Engine(r.program(), new RunOptions(0.01, 1, List.of(
                new Stimulus(2.5, 1, Stimulus.Kind.SENSOR, 205 * 6 + 4, 1, "touch"))));
        double[] sum = new double[1];
        e.addObserver((JointSink) (tick, time, commanded) -> sum[0] += commanded[0]);
        // the IDE's breakpoint watcher reads every module's state and exit after each tick: no allocation either
        e.addObserver(new org.parpe.core.run.Breakpoints().watch(e, () -> { }));
        // plate actions (PARSL.md §14) reach their sink without allocating
        long[] actions = new long[1];
        e.addPlateSink((tick, time, acts, where) -> actions[0]++);
        e.start();
        // a live view asks for every module's state at every tick (Engine.moduleStates): no allocation either
        int[] inst = new int[e.moduleIds().length];
        int[] state = new int[inst.length];
        for (int i = 0; i < 30_000; i++) {
            e.step(); // warm up: class loading and JIT compilation allocate, the ticks themselves do not
            e.moduleStates(inst, state);
        }
        long bytes = fewestBytes(10_000, () -> {
            e.step();
            e.moduleStates(inst, state);
        });
        assertEquals(0, bytes, "10000 ticks (with entry changes, stimuli, ifs, exits, plate actions) allocated "
                + bytes + " bytes");
        assertTrue(actions[0] > 100, "plate actions were emitted on " + actions[0] + " ticks");
    }

    /**
     * The 1 000-module snake of {@code parpe bench --only core} (issue 36): after warm-up, a
     * scheduler tick allocates not one byte.
     */
    @Test
    void benchmarkSnakeTicksAllocateNothing() {
        String script = "<program><robot><structure><body elements=\"0..999\"/></structure></robot>"
                + "<parameters><amp value=\"30\"/></parameters>"
                + "<controls><speed type=\"slider\" min=\"0.1\" max=\"5\" value=\"1\"/></controls>"
                + "<main><go/></main><behaviors><go><wave group=\"body\" phase=\"1/$count\" period=\"2/$speed\"/></go></behaviors>"
                + "<automata><wave states=\"crest, trough\"/></automata>"
                + "<states><crest angles=\"amp*sin(2*pi*$phase) + 2*cos(pi*$index/$count)\"/>"
                + "<trough angles=\"-amp*sin(2*pi*$phase + 0.5) - 5*$cycle/($cycle+1)\"/></states></program>";
        LoadResult r = ScriptLoader.loadText(Path.of("bench-snake.xml"), script, Map.of());
        assertTrue(r.ok(), r.diagnostics()::toString);
        Engine e = new Engine(r.program(), RunOptions.defaults());
        e.start();
        for (int i = 0; i < 5_000; i++) {
            e.step(); // warm up: class loading and JIT compilation allocate, the ticks themselves do not
        }
        long bytes = fewestBytes(2_000, e::step);
        assertEquals(0, bytes, "2000 ticks of the 1000-module snake allocated " + bytes + " bytes");
    }

    /**
     * The bytes this thread allocates running {@code tick} {@code ticks} times, the fewest of
     * three rounds: a tick that allocates does so in every round, while a one-off allocation of
     * the JVM on this thread (a deoptimisation after late JIT compilation) hits one round only.
     */
    private static long fewestBytes(int ticks, Runnable tick) {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long fewest = Long.MAX_VALUE;
        for (int round = 0; round < 3; round++) {
            long before = mx.getThreadAllocatedBytes(Thread.currentThread().getId());
            for (int i = 0; i < ticks; i++) {
                tick.run();
            }
            fewest = Math.min(fewest, mx.getThreadAllocatedBytes(Thread.currentThread().getId()) - before);
        }
        return fewest;
    }

    @Test
    void traceNumbersAreFormattedWithoutAllocating() {
        org.parpe.core.run.TraceWriter w = new org.parpe.core.run.TraceWriter(java.io.Writer.nullWriter());
        w.start(new org.parpe.core.run.RunInfo(null, new int[] {0, 1, 2, 3}, 0.01));
        double[] values = {0.0078125, -123456.7890125, 1e15 + 0.5, 2.5e-6};
        for (int i = 0; i < 50_000; i++) {
            w.accept(i, i * 0.01, values); // warm up
        }
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long before = mx.getThreadAllocatedBytes(Thread.currentThread().getId());
        for (int i = 0; i < 10_000; i++) {
            w.accept(i, i * 0.01, values);
        }
        long bytes = mx.getThreadAllocatedBytes(Thread.currentThread().getId()) - before;
        assertTrue(bytes < 10_000, "10000 trace rows (exact ties among them) allocated " + bytes + " bytes");
    }
}
