package org.parpe.gui.run;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.run.Engine;
import org.parpe.core.run.EngineStatus;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.ScriptRuntimeError;

/**
 * Runs an {@link Engine} on its own thread. The UI talks to it only through a command queue
 * drained at tick boundaries (control changes) and volatile flags (stop, pause, speed); the
 * engine thread publishes an immutable {@link EngineStatus} that the UI reads on its own timer.
 * The end of a run is reported with {@code Display.asyncExec}, never {@code syncExec}.
 */
public final class RunController {
    private static final long STATUS_EVERY_NS = 20_000_000L;
    private static final double MAX_LAG_S = 0.25;

    private final Display display;
    private final ConcurrentLinkedQueue<Consumer<Engine>> commands = new ConcurrentLinkedQueue<>();
    private volatile boolean stop;
    private volatile boolean paused;
    private volatile Speed speed = Speed.REAL_TIME;
    private volatile EngineStatus status;
    private volatile Thread thread;
    private volatile String lastError = "";

    public RunController(Display display) {
        this.display = display;
    }

    /** Whether a run is going on. */
    public boolean running() {
        Thread t = thread;
        return t != null && t.isAlive();
    }

    /** Builds the engine of a run on the engine thread (opening the simulator and the bus takes time). */
    @FunctionalInterface
    public interface Setup {
        /**
         * Returns the engine with its sinks and source attached; adds what must be closed after
         * the run to {@code resources}.
         *
         * @throws Exception with a message for the user when something cannot be opened
         */
        Engine build(List<AutoCloseable> resources) throws Exception;
    }

    /**
     * Builds and runs an engine on a new thread.
     *
     * @param runFor stop after this much simulated time (negative: when the program ends)
     * @param onEnd  runs on the UI thread with the outcome
     */
    public synchronized void start(Setup setup, double runFor, Consumer<RunOutcome> onEnd) {
        if (running()) {
            throw new IllegalStateException("a run is already going on");
        }
        commands.clear();
        stop = false;
        paused = false;
        status = null;
        lastError = "";
        Thread t = new Thread(() -> {
            List<AutoCloseable> resources = new ArrayList<>();
            RunOutcome outcome = prepareAndRun(setup, runFor, resources);
            close(resources);
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

    private RunOutcome prepareAndRun(Setup setup, double runFor, List<AutoCloseable> resources) {
        try {
            Engine engine = setup.build(resources);
            return stop ? new RunOutcome(RunOutcome.Status.STOPPED, 0, "") : loop(engine, runFor);
        } catch (RuntimeException | LinkageError e) {
            lastError = "internal error while preparing the run (" + e + "); details for a bug report in "
                    + CrashLog.write("preparing the run", e);
        } catch (Exception e) {
            lastError = e.getMessage() == null ? e.toString() : e.getMessage();
        }
        return new RunOutcome(RunOutcome.Status.ERROR, 0, lastError);
    }

    private RunOutcome loop(Engine engine, double runFor) {
        RunOutcome outcome;
        try {
            engine.start();
            outcome = ticks(engine, runFor);
        } catch (ScriptRuntimeError e) {
            outcome = new RunOutcome(RunOutcome.Status.ERROR, engine.time(), e.getMessage());
        } catch (RuntimeException | LinkageError e) {
            String file = CrashLog.write("engine thread", e);
            outcome = new RunOutcome(RunOutcome.Status.ERROR, engine.time(),
                    "internal error during the run (" + e + "); details for a bug report in " + file);
        }
        lastError = outcome.message();
        try {
            engine.finish(outcome);
        } catch (RuntimeException e) {
            CrashLog.write("finishing the run", e);
        }
        status = safeStatus(engine);
        return outcome;
    }

    private RunOutcome ticks(Engine engine, double runFor) {
        long wall0 = System.nanoTime();
        double sim0 = 0;
        long lastStatus = 0;
        Speed pacedAt = speed;
        while (true) {
            for (Consumer<Engine> c; (c = commands.poll()) != null;) {
                c.accept(engine);
            }
            if (stop) {
                return new RunOutcome(RunOutcome.Status.STOPPED, engine.time(), "");
            }
            if (paused || speed != pacedAt) {
                if (paused) {
                    LockSupport.parkNanos(20_000_000L);
                }
                pacedAt = speed;
                wall0 = System.nanoTime();
                sim0 = Math.max(0, engine.time());
                continue;
            }
            boolean more = engine.step();
            long now = System.nanoTime();
            if (now - lastStatus > STATUS_EVERY_NS || !more) {
                status = engine.status();
                lastStatus = now;
            }
            if (!more || runFor >= 0 && engine.time() >= runFor - 1e-9) {
                return new RunOutcome(RunOutcome.Status.COMPLETED, engine.time(), "");
            }
            double factor = pacedAt.factor();
            if (Double.isFinite(factor)) {
                double ahead = (engine.time() - sim0) / factor - (now - wall0) / 1e9;
                if (ahead > 0) {
                    LockSupport.parkNanos((long) (ahead * 1e9));
                } else if (ahead < -MAX_LAG_S) {
                    // The plant cannot keep up: carry on from here rather than racing to catch up.
                    wall0 = now;
                    sim0 = engine.time();
                }
            }
        }
    }

    private static EngineStatus safeStatus(Engine engine) {
        try {
            return engine.status();
        } catch (RuntimeException e) {
            return null;
        }
    }

    private static void close(List<AutoCloseable> resources) {
        for (int i = resources.size() - 1; i >= 0; i--) {
            try {
                resources.get(i).close();
            } catch (Exception e) {
                CrashLog.write("closing " + resources.get(i), e);
            }
        }
    }

    /** Queues a slider or text control change for the next tick boundary. */
    public void setControl(String name, double value) {
        commands.add(e -> {
            try {
                e.setControl(name, value);
            } catch (IllegalArgumentException ex) {
                lastError = ex.getMessage();
            }
        });
    }

    /** Queues a radio control change for the next tick boundary. */
    public void setControlWord(String name, String word) {
        commands.add(e -> {
            try {
                e.setControlWord(name, word);
            } catch (IllegalArgumentException ex) {
                lastError = ex.getMessage();
            }
        });
    }

    /** Asks the run to stop at the next tick boundary (the Stop button only sets this flag). */
    public void stop() {
        stop = true;
        Thread t = thread;
        if (t != null) {
            LockSupport.unpark(t);
        }
    }

    /** Pauses or resumes the run. */
    public void setPaused(boolean p) {
        paused = p;
    }

    public boolean paused() {
        return paused;
    }

    /** Changes the pace (takes effect at the next tick). */
    public void setSpeed(Speed s) {
        speed = s;
    }

    public Speed speed() {
        return speed;
    }

    /** The latest published status, or null before the first tick. */
    public EngineStatus status() {
        return status;
    }

    /** The message of the last failed control change or run error, or empty. */
    public String lastError() {
        return lastError;
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
