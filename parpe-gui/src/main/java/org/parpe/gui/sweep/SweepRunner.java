package org.parpe.gui.sweep;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;
import org.eclipse.swt.SWTException;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.LoadResult;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.core.run.TargetException;
import org.parpe.gui.run.CrashLog;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;
import org.parpe.sim.sweep.Cancellation;
import org.parpe.sim.sweep.Evaluation;
import org.parpe.sim.sweep.Evaluator;
import org.parpe.sim.sweep.OptimizationResult;
import org.parpe.sim.sweep.OptimizeSpec;
import org.parpe.sim.sweep.Optimizer;
import org.parpe.sim.sweep.Sweep;
import org.parpe.sim.sweep.SweepException;
import org.parpe.sim.sweep.SweepListener;
import org.parpe.sim.sweep.SweepResult;
import org.parpe.sim.sweep.SweepRow;
import org.parpe.sim.sweep.SweepSpec;

/**
 * Runs one sweep or optimisation on its own thread (and the engine's workers) and hands what
 * happens to the UI thread with {@link Display#asyncExec}: rows and progress are collected in
 * a queue and delivered in batches, at most one delivery waiting at a time, so that a fast
 * sweep cannot flood the event loop. The UI thread never waits for it; {@link #stop()} only
 * sets the engine's {@link Cancellation}.
 */
final class SweepRunner {
    /** What the dialog is told, always on the UI thread. */
    interface Events {
        /** Rows that arrived since the last call (in the engine's order), and the progress now. */
        void rows(List<SweepRow> rows, int done, int total);

        /**
         * The end, after the last {@link #rows}: {@code all} is the engine's final list of rows
         * for an optimisation, null for a sweep (its rows came in order through {@link #rows})
         * or a failure; {@code cancelled} whether Stop ended it, {@code error} a one-line message or null.
         */
        void finished(List<SweepRow> all, boolean cancelled, String error);

        /** Problems with a place (a robot that does not fit the script, a bad configuration file) for Problems. */
        void problems(List<Diagnostic> problems);
    }

    private final Display display;
    private final Events events;
    private final Cancellation cancellation = new Cancellation();
    private final ConcurrentLinkedQueue<SweepRow> queue = new ConcurrentLinkedQueue<>();
    private final AtomicBoolean posted = new AtomicBoolean();
    private volatile int done;
    private volatile int total;
    private volatile boolean running = true;

    private SweepRunner(Display display, Events events) {
        this.display = display;
        this.events = events;
    }

    /** Starts a sweep of {@code spec} on {@code jobs} threads. */
    static SweepRunner sweep(Display display, Evaluator.Settings settings, SweepSpec spec, int jobs, Events events) {
        SweepRunner r = new SweepRunner(display, events);
        r.total = spec.size();
        r.start(() -> {
            r.checkRobot(settings);
            // The dialog keeps what its table and plot need (Results); the engine lets each row go once it is handed over.
            SweepResult result = new Sweep(Evaluator.load(settings), spec).run(0, spec.size(), jobs, r.listener(), r.cancellation, false);
            r.end(null, result.cancelled(), null);
        });
        return r;
    }

    /** Starts an optimisation of {@code spec} on {@code jobs} threads. */
    static SweepRunner optimise(Display display, Evaluator.Settings settings, OptimizeSpec spec, int jobs, Events events) {
        SweepRunner r = new SweepRunner(display, events);
        r.total = spec.budget();
        r.start(() -> {
            r.checkRobot(settings);
            OptimizationResult result = new Optimizer(Evaluator.load(settings), spec).run(jobs, r.listener(), r.cancellation);
            List<SweepRow> rows = new ArrayList<>();
            for (Evaluation e : result.evaluations()) {
                rows.add(e.row());
            }
            r.end(rows, result.cancelled(), null);
        });
        return r;
    }

    /** Work that may refuse to start with a message for the user. */
    private interface Work {
        void run() throws SweepException;
    }

    private void start(Work work) {
        Thread t = new Thread(() -> {
            try {
                work.run();
            } catch (SweepException e) {
                end(null, false, StartRequest.inDialogWords(e.text()).toString());
            } catch (RuntimeException | Error e) {
                end(null, false, ToolMsg.SWEEP_INTERNAL_ERROR.text(e, CrashLog.write("running a sweep", e)));
            }
        }, "parpe-sweep-dialog");
        t.setDaemon(true);
        t.start();
    }

    /**
     * Builds the robot once to hand its problems, with their places, to the Problems view;
     * {@link Evaluator#load} then refuses to start with the first of them as its message.
     */
    private void checkRobot(Evaluator.Settings s) {
        LoadResult loaded = ScriptDocument.load(s.script(), s.text(), s.fixed());
        if (loaded.program() == null) {
            return;
        }
        String spec = SimTarget.AUTO.equals(s.robot()) ? SimTarget.autoSpec(loaded.program()) : s.robot();
        try (Simulator sim = SimTarget.create(spec, loaded.program().moduleIds(), d -> { })) {
            sim.moduleIds();
        } catch (TargetException e) {
            if (!e.diagnostics().isEmpty()) {
                List<Diagnostic> found = List.copyOf(e.diagnostics());
                post(() -> events.problems(found));
            }
        }
    }

    private SweepListener listener() {
        return new SweepListener() {
            @Override
            public void progress(int finished, int of) {
                done = finished;
                total = of;
                deliver();
            }

            @Override
            public void row(SweepRow row) {
                queue.add(row);
                deliver();
            }
        };
    }

    /** Posts one delivery unless one is already waiting (it will take what arrived meanwhile). */
    private void deliver() {
        if (posted.compareAndSet(false, true)) {
            post(() -> {
                posted.set(false);
                List<SweepRow> batch = new ArrayList<>();
                for (SweepRow r = queue.poll(); r != null; r = queue.poll()) {
                    batch.add(r);
                }
                events.rows(batch, done, total);
            });
        }
    }

    private void end(List<SweepRow> all, boolean cancelled, String error) {
        post(() -> {
            List<SweepRow> last = new ArrayList<>();
            for (SweepRow r = queue.poll(); r != null; r = queue.poll()) {
                last.add(r);
            }
            if (!last.isEmpty()) {
                events.rows(last, done, total);
            }
            running = false;
            events.finished(all, cancelled || cancellation.cancelled(), error);
        });
    }

    private void post(Runnable r) {
        try {
            if (!display.isDisposed()) {
                display.asyncExec(r);
            }
        } catch (SWTException closed) {
            // The display closed while the sweep was ending: nobody is left to tell.
        }
    }

    /** Asks the engine to stop at its next tick; returns at once. */
    void stop() {
        cancellation.cancel();
    }

    /** Whether the end has not been delivered yet. */
    boolean running() {
        return running;
    }
}
