package org.parpe.sim;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.TraceColumns;
import org.parpe.sim.config.RobotConfigs;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;

/**
 * A simulator tick in its steady state allocates (next to) nothing (issue 36; "the tick loop
 * allocates nothing", docs/architecture.md): the bytes the JVM counts for this thread over many
 * ticks of the scheduler driving the simulator, reading its sensors and its trace columns, after
 * a warm-up in which buffers reach their size and the JIT compiles the tick. Measured by the JVM
 * ({@code ThreadMXBean#getThreadAllocatedBytes}), not by time. On the centipede the tick
 * allocated 515 KB before issue 36 (ODE4j's solver arrays, contact joints and collision
 * temporaries, the island task framework).
 */
class TickAllocationTest {
    /** The bound of issue 36: 1 KB per tick, for the few objects the JVM itself makes now and then. */
    private static final long MAX_BYTES_PER_TICK = 1024;
    private static final int WARM_UP_TICKS = 1500;
    /** Ticks per measured window. */
    private static final int WINDOW_TICKS = 500;
    /** Windows measured at most: until the JIT has compiled the tick (on a busy machine it takes longer). */
    private static final int MAX_WINDOWS = 20;

    static String snake(int n) {
        return "<program><robot><structure><body elements=\"0.." + (n - 1) + "\"/></structure></robot>"
                + "<main><go/></main><behaviors><go><wave group=\"body\" phase=\"0.125\" period=\"1\"/></go></behaviors>"
                + "<automata><wave states=\"up, down\"/></automata>"
                + "<states><up angles=\"30\"/><down angles=\"-30\"/></states></program>";
    }

    /** The paper's centipede walk on the {@code centipede} generator's IDs. */
    static final Path CENTIPEDE = Path.of("../examples/centipede-walk.xml");

    @Test
    void snakeTickAllocatesNothing() throws Exception {
        assertSteadyTickAllocatesNothing("snake:n=8", snake(8), null);
    }

    @Test
    void centipedeTickAllocatesNothing() throws Exception {
        assertSteadyTickAllocatesNothing("centipede", Files.readString(CENTIPEDE), null);
    }

    /**
     * A world of rubble under and around the robot from its first step, with movable things in its
     * way (balls, chips, a cup) and a lever: contacts of the robot with fixed scenery, with objects,
     * and of objects with each other, the scenery's springs.
     */
    static final String RUBBLE_AND_OBJECTS = """
            <world time-limit="60" floor-friction="0.6">
              <start x="0" y="0" yaw="0"/>
              <rubble x0="-0.4" y0="-0.35" x1="1.2" y1="0.35" count="60" seed="7" min-size="0.008" max-size="0.02"/>
              <ball name="ball1" x="0.35" y="0.05"/>
              <ball name="ball2" x="0.45" y="-0.1" radius="0.02"/>
              <chip name="chip1" x="0.3" y="-0.05" radius="0.03" thickness="0.01"/>
              <cup name="cup1" x="0.5" y="0.15"/>
              <lever name="lever1" x="0.6" y="-0.2" yaw="90" length="0.15"/>
            </world>
            """;

    @Test
    void centipedeAmongRubbleAndObjectsTickAllocatesNothing(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("rubble-and-objects.xml");
        Files.writeString(file, RUBBLE_AND_OBJECTS);
        DiagnosticList found = new DiagnosticList();
        World world = WorldReader.read(file, found);
        assertNotNull(world, () -> found.all().toString());
        assertTrue(world.objects().size() == 5 && !world.solids().isEmpty(), "movable objects and rubble");
        assertSteadyTickAllocatesNothing("centipede", Files.readString(CENTIPEDE), world);
    }

    private static void assertSteadyTickAllocatesNothing(String robot, String script, World world) throws Exception {
        LoadResult r = ScriptLoader.loadText(Path.of("tick-allocation.xml"), script, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        DiagnosticList diags = new DiagnosticList();
        try (Simulator sim = new Simulator(RobotConfigs.resolve(robot, r.program().moduleIds(), diags), world)) {
            Engine engine = new Engine(r.program(), new RunOptions(Simulator.DEFAULT_TICK, 0, List.of()));
            engine.addPlant(sim);
            engine.setSensorSource(sim);
            engine.start();
            TraceColumns columns = sim.traceColumns();
            double[] row = new double[columns.names().length];
            ticks(engine, columns, row, WARM_UP_TICKS);
            // The steady state: windows of ticks until one allocates at most the bound. Until the JIT
            // has compiled the tick, the interpreter allocates what compiled code keeps in registers.
            com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
            long id = Thread.currentThread().getId();
            StringBuilder windows = new StringBuilder();
            for (int w = 0; w < MAX_WINDOWS; w++) {
                long before = mx.getThreadAllocatedBytes(id);
                ticks(engine, columns, row, WINDOW_TICKS);
                long perTick = (mx.getThreadAllocatedBytes(id) - before) / WINDOW_TICKS;
                if (perTick <= MAX_BYTES_PER_TICK) {
                    return;
                }
                windows.append(w == 0 ? "" : ", ").append(perTick);
            }
            fail(robot + (world == null ? "" : " in a world") + ": a tick allocates more than " + MAX_BYTES_PER_TICK
                    + " bytes in every window of " + WINDOW_TICKS + " ticks (bytes per tick: " + windows + ")");
        }
    }

    private static void ticks(Engine engine, TraceColumns columns, double[] row, int n) {
        for (int i = 0; i < n; i++) {
            engine.step();
            columns.values(row);
        }
    }
}
