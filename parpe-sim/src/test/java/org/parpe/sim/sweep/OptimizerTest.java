package org.parpe.sim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;

class OptimizerTest {
    private static final double DURATION = 3;

    @Test
    void optimisationBeatsTheScriptsDefaultsAndIsReproducible() throws Exception {
        Evaluator ev = Scripts.snake(DURATION, Map.of());
        SweepRow defaults = ev.run(new Point(0, 0, 0, Map.of(), 1), new Cancellation());
        OptimizeSpec spec = new OptimizeSpec(Objective.FORWARD_SPEED, Constraints.NONE, 24, 2, 1);
        OptimizationResult first = new Optimizer(ev, spec).run(2, SweepListener.NONE, new Cancellation());
        assertEquals(24, first.evaluations().size());
        Evaluation best = first.best().orElseThrow();
        assertTrue(best.score() > defaults.forwardSpeed() + 0.01,
                "best " + best.score() + " vs defaults " + defaults.forwardSpeed());
        // start 0 begins at the script's own values
        assertEquals(Map.of("bend", 10.0, "period", 4.0, "phase", 0.9), first.starts().get(0).get(0).row().values());
        double[] curve = first.bestSoFar();
        for (int i = 1; i < curve.length; i++) {
            assertTrue(curve[i] >= curve[i - 1]);
        }
        assertEquals(best.score(), curve[curve.length - 1]);
        OptimizationResult again = new Optimizer(ev, spec).run(1, SweepListener.NONE, new Cancellation());
        assertEquals(first.evaluations().stream().map(e -> e.row().values()).toList(),
                again.evaluations().stream().map(e -> e.row().values()).toList());
        assertEquals(best.score(), again.best().orElseThrow().score());
    }

    @Test
    void constraintsRankInfeasibleRunsBelowFeasibleOnes() throws Exception {
        Evaluator ev = Scripts.snake(1, Map.of());
        OptimizeSpec spec = new OptimizeSpec(Objective.DISTANCE, new Constraints(5, false), 8, 1, 3);
        OptimizationResult r = new Optimizer(ev, spec).run(1, SweepListener.NONE, new Cancellation());
        for (Evaluation e : r.evaluations()) {
            assertEquals(e.row().maxTiltDeg() <= 5, e.feasible(), e.toString());
        }
        r.best().ifPresent(b -> assertTrue(b.row().maxTiltDeg() <= 5));
    }

    @Test
    void theBestValuesBecomeTheDefaultsOfANewScript() throws Exception {
        Evaluator ev = Scripts.snake(1, Map.of());
        String text = ParameterDefaults.rewrite(Scripts.FILE, Scripts.SNAKE, ev.parameters(),
                Map.of("bend", 42.0, "phase", 0.125));
        assertTrue(text.contains("<bend   value=\"42\"  min=\"0\"   max=\"60\"/>"), text);
        assertTrue(text.contains("<phase  value=\"0.125\" min=\"0\"   max=\"1\"/>"), text);
        assertTrue(text.contains("<period value=\"4\"   min=\"0.5\" max=\"5\"/>"), text);
        LoadResult r = ScriptLoader.loadText(Scripts.FILE, text, Map.of());
        assertEquals(List.of(42.0, 4.0, 0.125), r.program().parameters().stream().map(p -> p.value()).toList());
    }

    @Test
    void aScriptWithoutBoundedParametersCannotBeOptimised() throws Exception {
        Evaluator ev = Scripts.snake(1, Map.of("bend", 10.0, "period", 2.0, "phase", 0.5));
        SweepException e = assertThrows(SweepException.class,
                () -> new Optimizer(ev, new OptimizeSpec(Objective.FORWARD_SPEED, Constraints.NONE, 10, 1, 0)));
        assertEquals("nothing to optimise: no parameter of sweep-snake.xml has both a min and a max (and is not"
                + " fixed with --param)", e.getMessage());
        assertFalse(new SearchSpace(ev.parameters(), java.util.Set.of()).parameters().isEmpty());
    }
}
