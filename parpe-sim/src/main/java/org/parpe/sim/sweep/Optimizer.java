package org.parpe.sim.sweep;

import org.parpe.sim.text.SimMsg;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import org.apache.commons.math3.exception.TooManyEvaluationsException;
import org.apache.commons.math3.optim.InitialGuess;
import org.apache.commons.math3.optim.MaxEval;
import org.apache.commons.math3.optim.MaxIter;
import org.apache.commons.math3.optim.SimpleBounds;
import org.apache.commons.math3.optim.nonlinear.scalar.GoalType;
import org.apache.commons.math3.optim.nonlinear.scalar.ObjectiveFunction;
import org.apache.commons.math3.optim.nonlinear.scalar.noderiv.CMAESOptimizer;
import org.apache.commons.math3.random.MersenneTwister;

/**
 * Searches a script's bounded parameters for the best gait with CMA-ES (Apache Commons Math's
 * {@link CMAESOptimizer}). {@code CMAESOptimizer} evaluates its population one point after
 * another, so parallelism comes from {@link OptimizeSpec#starts()} independent searches with
 * their own seeds that share the budget and run on the worker threads; a search that converges
 * early restarts from a random point while its share lasts. The result depends on the
 * specification and the seed only, not on the number of threads.
 */
public final class Optimizer {
    private static final double SIGMA = 0.3;

    private final Evaluator evaluator;
    private final OptimizeSpec spec;
    private final SearchSpace space;

    /** An optimisation of {@code evaluator}'s script; throws when there is nothing to search. */
    public Optimizer(Evaluator evaluator, OptimizeSpec spec) throws SweepException {
        spec.check();
        this.evaluator = evaluator;
        this.spec = spec;
        this.space = new SearchSpace(evaluator.parameters(), evaluator.fixed().keySet());
        if (space.dimension() == 0) {
            throw new SweepException(SimMsg.NOTHING_TO_OPTIMISE, evaluator.script());
        }
    }

    /** The searched parameters. */
    public SearchSpace space() {
        return space;
    }

    /**
     * Runs the searches on {@code jobs} threads until the budget is spent or
     * {@code cancellation}; the listener sees each evaluation as it finishes.
     */
    public OptimizationResult run(int jobs, SweepListener listener, Cancellation cancellation) {
        int n = spec.starts();
        List<List<Evaluation>> results = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            results.add(new ArrayList<>());
        }
        SweepListener shared = serialised(listener);
        AtomicInteger nextStart = new AtomicInteger();
        Runnable worker = () -> {
            try (Evaluator.Worker w = evaluator.worker()) {
                for (int s = nextStart.getAndIncrement(); s < n; s = nextStart.getAndIncrement()) {
                    search(w, s, spec.budget() / n + (s < spec.budget() % n ? 1 : 0), results.get(s), shared,
                            cancellation);
                }
            }
        };
        Sweep.runOn(Math.max(1, Math.min(jobs, n)), worker, cancellation);
        return new OptimizationResult(spec.objective(), results, cancellation.cancelled());
    }

    private static SweepListener serialised(SweepListener listener) {
        return new SweepListener() {
            private int done;

            @Override
            public synchronized void row(SweepRow row) {
                listener.row(row);
            }

            @Override
            public synchronized void progress(int ignored, int total) {
                listener.progress(++done, total);
            }
        };
    }

    /** One search: CMA-ES runs, restarted from random points while {@code budget} lasts. */
    private void search(Evaluator.Worker w, int start, int budget, List<Evaluation> out, SweepListener listener, Cancellation cancel) {
        int d = space.dimension();
        MersenneTwister random = new MersenneTwister(SweepSpec.mix(spec.seed(), start));
        int lambda = 4 + (int) Math.floor(3 * Math.log(d));
        Map<Map<String, Double>, Double> cache = new HashMap<>();
        double[] x0 = start == 0 ? space.defaults() : randomPoint(random, d);
        // Repeated points cost CMA-ES an evaluation but no simulation (cache): a small, mostly
        // integer space could otherwise restart forever without spending the budget.
        for (int round = 0; round < 10 * budget && !cancel.cancelled() && budget - out.size() >= 2; round++) {
            int left = budget - out.size();
            double[] lo = new double[d];
            double[] hi = new double[d];
            double[] sigma = new double[d];
            java.util.Arrays.fill(hi, 1);
            java.util.Arrays.fill(sigma, SIGMA);
            CMAESOptimizer cma = new CMAESOptimizer(Integer.MAX_VALUE, Double.NEGATIVE_INFINITY, true, 0, 0,
                    random, false, null);
            try {
                cma.optimize(new MaxEval(left), new MaxIter(Integer.MAX_VALUE),
                        new ObjectiveFunction(x -> fitness(w, start, x, budget, out, cache, listener, cancel)),
                        GoalType.MINIMIZE, new InitialGuess(x0), new SimpleBounds(lo, hi),
                        new CMAESOptimizer.Sigma(sigma), new CMAESOptimizer.PopulationSize(Math.min(lambda, left)));
            } catch (Stopped spent) {
                return;
            } catch (TooManyEvaluationsException cachedRepeats) {
                // the share was spent partly on repeated points: go on from a new point
            }
            x0 = randomPoint(random, d);
        }
    }

    /** What CMA-ES minimises: minus the score, or a penalty below every feasible score. */
    private double fitness(Evaluator.Worker w, int start, double[] x, int budget, List<Evaluation> out,
                           Map<Map<String, Double>, Double> cache, SweepListener listener, Cancellation cancel) {
        Map<String, Double> values = space.values(x);
        Double known = cache.get(values);
        if (known != null) {
            return known;
        }
        if (cancel.cancelled() || out.size() >= budget) {
            throw new Stopped();
        }
        int number = out.size();
        SweepRow row = w.run(new Point(number, number, 0, values, spec.seed()), cancel);
        if (row == null) {
            throw new Stopped();
        }
        double score = spec.objective().of(row);
        double violation = spec.constraints().violation(row);
        boolean feasible = violation == 0 && !Double.isNaN(score);
        out.add(new Evaluation(start, number, row, Double.isNaN(score) ? Double.NaN : score, feasible));
        listener.row(row);
        listener.progress(0, spec.budget());
        // Infeasible runs rank below every feasible one, the further off the worse.
        double f = feasible ? -score : 1e6 + violation;
        cache.put(values, f);
        return f;
    }

    private static double[] randomPoint(MersenneTwister random, int d) {
        double[] x = new double[d];
        for (int i = 0; i < d; i++) {
            x[i] = random.nextDouble();
        }
        return x;
    }

    /** Ends a search from inside the objective function when cancelled or out of budget. */
    private static final class Stopped extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Stopped() {
            super(null, null, false, false);
        }
    }
}
