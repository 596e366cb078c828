package org.parpe.cli.sim;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.SourceKind;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;

/**
 * Runs a program on a simulator as fast as possible for a given simulated time (or until
 * {@code <main>} ends): used by {@code parpe race}, the simulator benchmark and tests.
 */
public final class SimRun {
    private SimRun() {
    }

    /**
     * Runs {@code program} on {@code sim} as fast as possible for at most {@code duration} s
     * with tick {@code dt}; warnings and a run-time error go to {@code diags}.
     */
    public static RunOutcome run(Program program, Simulator sim, double duration, double dt, DiagnosticSink diags) {
        return Run.builder(program, new RunOptions(dt, 0, List.of()), diags)
                .plant(sim)
                .sensorSource(SourceKind.SIMULATOR, sim)
                .duration(duration)
                .build()
                .execute();
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
