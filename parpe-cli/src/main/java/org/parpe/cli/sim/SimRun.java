package org.parpe.cli.sim;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.sim.Simulator;

/**
 * Runs a program on a simulator as fast as possible for a given simulated time (or until
 * {@code <main>} ends): used by {@code parpe race}, the simulator benchmark and tests.
 */
public final class SimRun {
    private static final double EPS = 1e-9;

    private SimRun() {
    }

    /** Runs {@code program} on {@code sim} for at most {@code duration} s with tick {@code dt}; returns the simulated time reached. */
    public static double run(Program program, Simulator sim, double duration, double dt) {
        Engine engine = new Engine(program, new RunOptions(dt, 0, List.of()));
        engine.addSink(sim);
        engine.setSensorSource(sim);
        engine.start();
        RunOutcome.Status status = RunOutcome.Status.COMPLETED;
        try {
            for (long k = 0; k * dt <= duration + EPS; k++) {
                if (!engine.step()) {
                    break;
                }
            }
        } finally {
            engine.finish(new RunOutcome(status, engine.time(), ""));
        }
        return sim.time();
    }

    /** Loads a script from text (benchmarks, tests); throws if it has errors. */
    public static Program load(String name, String text) {
        LoadResult r = ScriptLoader.loadText(Path.of(name), text, Map.of());
        if (r.program() == null) {
            throw new IllegalStateException("benchmark script " + name + " does not load: " + r.diagnostics());
        }
        return r.program();
    }
}
