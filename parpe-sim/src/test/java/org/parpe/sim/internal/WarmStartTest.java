package org.parpe.sim.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.sim.config.RobotConfigs;

/**
 * Warm starting of PARPE's QuickStep ({@code org.ode4j.ode.internal.WarmStart}): each solver row
 * starts from 0.9 of the force it ended the step before with, instead of from zero. An 8-module
 * snake's travelling wave (±30°, the states of a two-state automaton, 1 s period, a quarter of a period between modules, as examples/hello-snake.xml) for 10 s at
 * the default 5 ms step: with 10 cold iterations the solver is not converged (the snake goes 0.69 m,
 * with 100 iterations 0.81 m), warm-started it is (0.79 m); and it stays deterministic and
 * allocation-free.
 */
class WarmStartTest {
    private static final double SECONDS = 10;
    private static final double TICK = 0.01;

    /** The snake's run; returns the x of its centre of mass and then every piece's position. */
    private static double[] run(PhysicsParams params) {
        try (PhysicsWorld world = snake(params)) {
            for (int t = 0; t < Math.round(SECONDS / TICK); t++) {
                wave(world);
                world.advance(TICK);
            }
            double[] com = new double[3];
            world.centerOfMass(com);
            double[] out = new double[1 + 3 * world.pieceCount()];
            out[0] = com[0];
            for (int i = 0; i < world.pieceCount(); i++) {
                for (int k = 0; k < 3; k++) {
                    out[1 + 3 * i + k] = world.piecePosition(i).get(k);
                }
            }
            return out;
        }
    }

    private static PhysicsWorld snake(PhysicsParams params) {
        DiagnosticList diags = new DiagnosticList();
        Assembly a = Assembly.build(RobotConfigs.resolve("snake:n=8", IntStream.range(0, 8).toArray(), diags), diags);
        assertNotNull(a, () -> diags.all().toString());
        return new PhysicsWorld(a, params);
    }

    private static void wave(PhysicsWorld world) {
        for (int h = 0; h < world.hingeCount(); h++) {
            world.setTarget(h, Math.toRadians(30) * Math.signum(Math.sin(2 * Math.PI * (world.time() - 0.25 * h))));
        }
    }

    @Test
    void tenWarmStartedIterationsComeCloseToAHundredCold() {
        PhysicsParams cold = PhysicsParams.defaults();
        double converged = run(cold.withIterations(100))[0];
        double tenCold = run(cold)[0];
        double tenWarm = run(cold.withWarmStart(0.9))[0];
        String figures = "100 cold " + converged + " m, 10 cold " + tenCold + " m, 10 warm " + tenWarm + " m";
        assertTrue(converged > 0.2, figures);
        assertTrue(Math.abs(tenCold - converged) > 0.1 * converged, "10 cold iterations are not converged: " + figures);
        assertTrue(Math.abs(tenWarm - converged) < 0.05 * converged, "10 warm-started iterations are: " + figures);
    }

    @Test
    void warmStartedRunsAreBitIdentical() {
        PhysicsParams warm = PhysicsParams.defaults().withWarmStart(0.9);
        assertArrayEquals(run(warm), run(warm));
    }

    /** As {@code TickAllocationTest} for the default solver: windows of sub-steps until the JIT has compiled them. */
    @Test
    void warmStartedStepsAllocateNothing() {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        long perTick = Long.MAX_VALUE;
        try (PhysicsWorld world = snake(PhysicsParams.defaults().withWarmStart(0.9))) {
            for (int w = 0; w < 20 && perTick > 1024; w++) {
                long before = mx.getThreadAllocatedBytes(id);
                for (int t = 0; t < 500; t++) {
                    wave(world);
                    world.advance(TICK);
                }
                perTick = (mx.getThreadAllocatedBytes(id) - before) / 500;
            }
        }
        assertTrue(perTick <= 1024, "bytes per tick: " + perTick);
    }
}
