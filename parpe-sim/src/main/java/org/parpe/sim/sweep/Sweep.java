package org.parpe.sim.sweep;

import org.parpe.sim.text.SimMsg;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Runs the runs {@code [from, to)} of a {@link SweepSpec} on {@code jobs} threads, each run on a
 * fresh simulated robot, and hands the rows to the listener in combination order as soon as
 * every earlier row is in. The rows do not depend on the number of threads or on how a sweep
 * is split into shards.
 */
public final class Sweep {
    private final Evaluator evaluator;
    private final SweepSpec spec;

    /** A sweep of {@code spec} with {@code evaluator}'s script, robot and duration. */
    public Sweep(Evaluator evaluator, SweepSpec spec) throws SweepException {
        spec.check();
        for (Axis a : spec.axes()) {
            if (evaluator.fixed().containsKey(a.name())) {
                throw new SweepException(SimMsg.VARIED_AND_FIXED, a.name());
            }
        }
        this.evaluator = evaluator;
        this.spec = spec;
    }

    /** The specification. */
    public SweepSpec spec() {
        return spec;
    }

    /** Runs every run of the sweep. */
    public SweepResult run(int jobs, SweepListener listener, Cancellation cancellation) {
        return run(0, spec.size(), jobs, listener, cancellation);
    }

    /**
     * Runs runs {@code from} (inclusive) to {@code to} (exclusive) on {@code jobs} threads;
     * blocks until they are done or {@code cancellation} stops them. A failure of PARPE itself
     * in a run stops the others and is rethrown.
     */
    public SweepResult run(int from, int to, int jobs, SweepListener listener, Cancellation cancellation) {
        return run(from, to, jobs, listener, cancellation, true);
    }

    /**
     * As {@link #run(int, int, int, SweepListener, Cancellation)}; with {@code keep} false a row
     * is let go once the listener has it, and the result holds no rows (only whether it was
     * stopped): a caller that keeps what it needs itself (the IDE's dialog, a million runs) does
     * not hold every row twice.
     */
    public SweepResult run(int from, int to, int jobs, SweepListener listener, Cancellation cancellation, boolean keep) {
        if (from < 0 || to > spec.size() || from > to || jobs < 1) {
            throw new IllegalArgumentException("runs " + from + ".." + to + " of " + spec.size() + " on " + jobs + " jobs");
        }
        Ordered ordered = new Ordered(from, to, listener, keep);
        AtomicInteger next = new AtomicInteger(from);
        Runnable worker = () -> {
            try (Evaluator.Worker w = evaluator.worker()) {
                for (int i = next.getAndIncrement(); i < to && !cancellation.cancelled(); i = next.getAndIncrement()) {
                    SweepRow row = w.run(spec.point(i), cancellation);
                    if (row != null) {
                        ordered.add(row);
                    }
                }
            }
        };
        runOn(Math.min(jobs, Math.max(1, to - from)), worker, cancellation);
        return new SweepResult(ordered.rows(), ordered.delivered() < to - from);
    }

    /**
     * Runs {@code worker} on {@code n} threads (the calling thread is one of them) and waits for
     * all; the first failure of a worker cancels the others and is rethrown on the calling thread.
     */
    static void runOn(int n, Runnable worker, Cancellation cancellation) {
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Runnable guarded = () -> {
            try {
                worker.run();
            } catch (RuntimeException | Error e) {
                failure.compareAndSet(null, e);
                cancellation.cancel();
            }
        };
        List<Thread> threads = new ArrayList<>();
        for (int i = 1; i < n; i++) {
            Thread t = new Thread(guarded, "parpe-sweep-" + i);
            t.setDaemon(true);
            t.start();
            threads.add(t);
        }
        guarded.run();
        boolean interrupted = false;
        for (Thread t : threads) {
            while (t.isAlive()) {
                try {
                    t.join();
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        Throwable t = failure.get();
        if (t instanceof RuntimeException r) {
            throw r;
        }
        if (t instanceof Error e) {
            throw e;
        }
    }

    /** Puts rows that finish in any order back into combination order for the listener. */
    private static final class Ordered {
        private final int from;
        private final int total;
        private final SweepRow[] done;
        private final SweepListener listener;
        private final boolean keep;
        private int next;
        private int finished;

        Ordered(int from, int to, SweepListener listener, boolean keep) {
            this.from = from;
            this.total = to - from;
            this.done = new SweepRow[total];
            this.listener = listener;
            this.keep = keep;
        }

        synchronized void add(SweepRow row) {
            done[row.point().index() - from] = row;
            finished++;
            listener.progress(finished, total);
            while (next < total && done[next] != null) {
                listener.row(done[next]);
                if (!keep) {
                    done[next] = null;
                }
                next++;
            }
        }

        /** How many rows the listener was given (in order). */
        synchronized int delivered() {
            return next;
        }

        synchronized List<SweepRow> rows() {
            List<SweepRow> rows = new ArrayList<>();
            for (int i = 0; keep && i < next; i++) {
                rows.add(done[i]);
            }
            return rows;
        }
    }
}
