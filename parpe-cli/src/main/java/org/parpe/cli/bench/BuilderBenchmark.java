package org.parpe.cli.bench;

import java.io.PrintStream;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;
import org.parpe.sim.build.BuildEdit;
import org.parpe.sim.build.RobotDraft;
import org.parpe.sim.config.PartType;

/**
 * {@code parpe bench --only builder}: what one edit of the robot builder costs on a 200-module
 * robot ({@code snake:n=200} made editable): making the edit, reading the edited text again and
 * assembling it to the bodies the Robot tab redraws from. Goal: 50 ms (issue 33). Two edits: an
 * initial angle changed in the middle of the chain, and a foot added at its end.
 */
public final class BuilderBenchmark implements Benchmark {
    private static final int MODULES = 200;
    /** Edits made before the timed ones, so the JIT has compiled the reader and the assembly (as in an IDE session). */
    private static final int WARMUP = 100;

    @Override
    public String name() {
        return "builder";
    }

    @Override
    public List<Goal> goals() {
        return List.of(Goal.atMost("builder.*_ms_median", 50));
    }

    @Override
    public void run(PrintStream out) {
        RobotDraft draft = RobotDraft.fromGenerator("bench-200.xml", "snake:n=" + MODULES);
        if (!draft.problems().isEmpty()) {
            throw new IllegalStateException("the benchmark robot does not assemble: " + draft.problems());
        }
        out.printf(Locale.ROOT, "builder.modules=%d%n", MODULES);
        out.printf(Locale.ROOT, "builder.bodies=%d%n", draft.bodies().size());
        String middle = "s" + MODULES / 2;
        int[] turn = {0};
        time(out, "angle", draft, d -> d.setAngle(middle, ++turn[0] % 2 == 0 ? 10 : -10));
        time(out, "add", draft, d -> d.add("s" + (MODULES - 1), 1, PartType.FOOT, 0, 0, 8, null));
    }

    /** The median time of making {@code edit} on {@code draft} and getting the new draft's bodies. */
    private static void time(PrintStream out, String name, RobotDraft draft, Function<RobotDraft, BuildEdit> edit) {
        double[] ms = new double[31];
        int bodies = 0;
        for (int i = -WARMUP; i < ms.length; i++) {
            long t0 = System.nanoTime();
            BuildEdit e = edit.apply(draft);
            bodies = draft.apply(e).bodies().size();
            if (i >= 0) {
                ms[i] = (System.nanoTime() - t0) / 1e6;
            }
        }
        Arrays.sort(ms);
        out.printf(Locale.ROOT, "builder.%s_ms_median=%.1f%n", name, ms[ms.length / 2]);
        out.printf(Locale.ROOT, "builder.%s_bodies=%d%n", name, bodies);
    }
}
