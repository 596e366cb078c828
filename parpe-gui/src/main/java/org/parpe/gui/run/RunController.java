package org.parpe.gui.run;

import org.parpe.gui.text.UiMsg;
import java.util.function.Consumer;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.run.Breakpoints;
import org.parpe.core.run.Engine;
import org.parpe.core.run.EngineStatus;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.TargetException;
import org.parpe.core.run.WallClockPacer;

/**
 * Runs a {@link Run} on its own thread. The run is assembled by the core's {@link Run.Builder},
 * as on the command line; this class only owns the thread, the pacing (speed and pause, a
 * {@link WallClockPacer}) and the published status. Its one stop flag is the engine's. The UI
 * talks to the engine through thread-safe calls applied at tick boundaries (controls, stop);
 * the engine thread publishes an immutable {@link EngineStatus} that the UI reads on its own
 * timer. The end of a run is reported with {@code Display.asyncExec}, never {@code syncExec}.
 */
public final class RunController {
    private static final long STATUS_EVERY_NS = 20_000_000L;

    private final Display display;
    private final WallClockPacer pacer = new WallClockPacer(Speed.REAL_TIME.factor());
    private volatile Speed speed = Speed.REAL_TIME;
    private volatile EngineStatus status;
    private final LiveStates live = new LiveStates();
    private final Breakpoints breakpoints = new Breakpoints();
    private volatile Thread thread;
    private volatile Engine engine;
    private volatile boolean hardwarePaced;
    private volatile JointSink extraObserver;

    public RunController(Display display) {
        this.display = display;
    }

    /** Whether a run is going on (being assembled or ticking). */
    public boolean running() {
        Thread t = thread;
        return t != null && t.isAlive();
    }

    /** Attaches the run's targets on the engine thread (opening the simulator and the bus takes time). */
    @FunctionalInterface
    public interface Setup {
        /**
         * Attaches targets and observers to {@code run}.
         *
         * @throws TargetException when a target cannot be used; its diagnostics say why
         */
        void attach(Run.Builder run) throws TargetException;
    }

    /**
     * Assembles and runs {@code run} on a new thread.
     *
     * @param setup   attaches the targets, on the engine thread
     * @param runFor  stop after this much simulated time (negative: when the program ends)
     * @param onEnd   runs on the UI thread with the outcome
     * @param onCrash told (on the engine thread) about a failure of PARPE itself, with the crash file
     */
    public synchronized void start(Run.Builder run, Setup setup, double runFor, Consumer<RunOutcome> onEnd,
                                   Consumer<String> onCrash) {
        if (running()) {
            throw new IllegalStateException("a run is already going on");
        }
        status = null;
        engine = run.engine();
        pacer.setPaused(false);
        Thread t = new Thread(() -> {
            RunOutcome outcome = assembleAndRun(run, setup, runFor, onCrash);
            // a run stopped while paused at a breakpoint is no longer there
            breakpoints.clearHit();
            try {
                if (!display.isDisposed()) {
                    display.asyncExec(() -> onEnd.accept(outcome));
                }
            } catch (org.eclipse.swt.SWTException e) {
                // The window closed while the run was ending: nobody is left to tell.
            }
        }, "parpe-engine");
        t.setDaemon(true);
        thread = t;
        t.start();
    }

    private RunOutcome assembleAndRun(Run.Builder builder, Setup setup, double runFor, Consumer<String> onCrash) {
        Engine e = builder.engine();
        try {
            setup.attach(builder);
        } catch (TargetException ex) {
            builder.abandon();
            ex.diagnostics().forEach(builder.diagnostics()::report);
            return new RunOutcome(RunOutcome.Status.ERROR, 0, ex.getMessage());
        } catch (RuntimeException | LinkageError ex) {
            builder.abandon();
            return crashed(e, UiMsg.DURING_PREPARING, ex, onCrash);
        }
        if (runFor >= 0) {
            builder.duration(runFor);
        }
        // Hardware cannot go faster than the wall clock: the faster speeds pace it at real time.
        hardwarePaced = builder.realtimeRequired();
        applySpeed();
        builder.pacer(pacer);
        builder.observer(new StatusPublisher(e));
        JointSink extra = extraObserver;
        if (extra != null) {
            builder.observer(extra);
        }
        builder.observer(breakpoints.watch(e, () -> {
            // the views show the tick the run stopped at, not the last one published
            status = e.status();
            live.publish(e, e.tick(), e.entryIndex());
            pacer.setPaused(true);
        }));
        Run run = builder.build();
        try {
            RunOutcome outcome = run.execute();
            status = safeStatus(e);
            return outcome;
        } catch (RuntimeException | LinkageError ex) {
            return crashed(e, UiMsg.DURING_RUN, ex, onCrash);
        }
    }

    private RunOutcome crashed(Engine e, UiMsg during, Throwable ex, Consumer<String> onCrash) {
        // the crash file is for the bug report: English, whatever the IDE speaks
        String file = CrashLog.write(org.parpe.core.text.Message.of(during).format(java.util.Locale.ENGLISH), ex);
        String message = UiMsg.INTERNAL_ERROR_RUN.text(during.text(), ex, file);
        onCrash.accept(message);
        return new RunOutcome(RunOutcome.Status.ERROR, e.time(), message);
    }

    private static EngineStatus safeStatus(Engine engine) {
        try {
            return engine.status();
        } catch (RuntimeException e) {
            return null;
        }
    }

    /** Publishes the engine's status for the UI at most every 20 ms of wall-clock time. */
    private final class StatusPublisher implements JointSink {
        private final Engine e;
        private long last;

        StatusPublisher(Engine e) {
            this.e = e;
            live.start(e);
        }

        @Override
        public void accept(long tick, double time, double[] commanded) {
            long now = System.nanoTime();
            if (now - last > STATUS_EVERY_NS) {
                status = e.status();
                live.publish(e, tick, status.entryIndex());
                last = now;
            }
        }

        @Override
        public void finish(RunOutcome outcome) {
            status = e.status();
        }
    }

    /** Asks the run to stop at the next tick boundary (the Stop button only sets the engine's flag). */
    public void stop() {
        Engine e = engine;
        if (e != null) {
            e.requestStop();
        }
    }

    /** Pauses or resumes the run (resuming also goes on from a breakpoint reached). */
    public void setPaused(boolean p) {
        if (!p) {
            breakpoints.clearHit();
        }
        pacer.setPaused(p);
    }

    /** Adds {@code o} as an observer of the following runs ({@code null}: none); for the benchmark. */
    public void observeRuns(JointSink o) {
        extraObserver = o;
    }

    /** The diagrams' breakpoints; a run pauses at the tick one is reached. */
    public Breakpoints breakpoints() {
        return breakpoints;
    }

    public boolean paused() {
        return pacer.paused();
    }

    /** Changes the pace (takes effect at the next tick). */
    public void setSpeed(Speed s) {
        speed = s;
        applySpeed();
    }

    private void applySpeed() {
        pacer.setFactor(hardwarePaced ? Math.min(1, speed.factor()) : speed.factor());
    }

    public Speed speed() {
        return speed;
    }

    /** Each module's state as the run last published it (with the status), for live views. */
    public LiveStates live() {
        return live;
    }

    /** The latest published status, or null before the first tick. */
    public EngineStatus status() {
        return status;
    }

    /** The engine of the current or last run (null before the first run). */
    public Engine engine() {
        return engine;
    }

    /** Waits up to {@code millis} for the engine thread to end (tests, shutdown). */
    public boolean join(long millis) throws InterruptedException {
        Thread t = thread;
        if (t != null) {
            t.join(millis);
            return !t.isAlive();
        }
        return true;
    }
}
