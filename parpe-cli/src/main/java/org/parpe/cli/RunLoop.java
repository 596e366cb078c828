package org.parpe.cli;

import java.io.PrintStream;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.function.Consumer;
import org.parpe.core.run.Engine;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.ScriptRuntimeError;
import org.parpe.core.run.TraceColumns;
import org.parpe.core.run.TraceWriter;

/**
 * Owns the clock of a headless run: steps the engine tick by tick until {@code <main>} ends,
 * the duration is reached (PARSL.md §13 rule 1) or the user interrupts, pacing to the wall
 * clock when a target asks for it.
 */
final class RunLoop {
    private static final double EPS = 1e-9;
    private final RunSetup setup;
    private final PrintStream err;
    private volatile boolean interrupted;

    RunLoop(RunSetup setup, PrintStream err) {
        this.setup = setup;
        this.err = err;
    }

    /** Runs; returns the exit code (0, or 3 after a run-time error). */
    int run(Writer traceOut, boolean traceToStdout) throws Exception {
        Engine engine = new Engine(setup.program(), setup.options());
        engine.setWarningSink(d -> err.println(d.format()));
        TraceWriter trace = null;
        if (traceOut != null) {
            trace = new TraceWriter(traceOut);
            for (TraceColumns c : setup.columns()) {
                trace.addColumns(c);
            }
            engine.addSink(trace);
        }
        for (JointSink s : setup.sinks()) {
            engine.addSink(s);
        }
        if (setup.sensorSource() != null) {
            engine.setSensorSource(setup.sensorSource());
        }
        CountDownLatch done = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            interrupted = true;
            try {
                done.await(java.util.concurrent.TimeUnit.SECONDS.toMillis(3), java.util.concurrent.TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "parpe-interrupt");
        Runtime.getRuntime().addShutdownHook(hook);
        RunOutcome outcome;
        int code = 0;
        try {
            outcome = loop(engine);
            if (outcome.status() == RunOutcome.Status.STOPPED) {
                err.println("parpe: stopped at t=" + String.format(Locale.ROOT, "%.3f", outcome.time()) + " s");
            }
        } catch (ScriptRuntimeError e) {
            err.println(e.getMessage());
            outcome = new RunOutcome(RunOutcome.Status.ERROR, engine.time(), e.getMessage());
            code = 3;
        }
        try {
            engine.finish(outcome);
            for (Consumer<RunOutcome> f : setup.finishers()) {
                f.accept(outcome);
            }
            if (traceOut != null && !traceToStdout) {
                traceOut.close();
            } else if (traceOut != null) {
                traceOut.flush();
            }
        } finally {
            done.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException shuttingDown) {
                // the JVM is exiting because of Ctrl-C: the hook is running and waits for us
            }
        }
        return code;
    }

    private RunOutcome loop(Engine engine) throws InterruptedException {
        double dt = engine.dt();
        double limit = setup.duration();
        Progress progress = Progress.forStderr(err, limit);
        long wallStart = System.nanoTime();
        engine.start();
        for (long k = 0; ; k++) {
            if (k * dt > limit + EPS) {
                return new RunOutcome(RunOutcome.Status.COMPLETED, engine.time(), "");
            }
            if (interrupted || engine.stopRequested()) {
                return new RunOutcome(RunOutcome.Status.STOPPED, engine.time(), "");
            }
            if (setup.realtime()) {
                long due = wallStart + (long) (k * dt * 1e9);
                long wait = due - System.nanoTime();
                if (wait > 0) {
                    Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
                }
            }
            boolean more = engine.step();
            progress.update(engine.time());
            if (!more) {
                progress.done();
                return new RunOutcome(RunOutcome.Status.COMPLETED, engine.time(), "");
            }
        }
    }

    /** Closes what the targets opened, reporting (not throwing) failures. */
    static void closeAll(RunSetup setup, PrintStream err) {
        List<AutoCloseable> list = setup.closeables();
        for (int i = list.size() - 1; i >= 0; i--) {
            try {
                list.get(i).close();
            } catch (Exception e) {
                err.println("parpe: warning: while closing: " + e.getMessage());
            }
        }
    }

    /** A one-line progress report on a terminal's standard error, for long runs. */
    static final class Progress {
        private final PrintStream err;
        private final double limit;
        private final boolean enabled;
        private final long start = System.nanoTime();
        private long last;
        private boolean shown;

        private Progress(PrintStream err, double limit, boolean enabled) {
            this.err = err;
            this.limit = limit;
            this.enabled = enabled;
        }

        static Progress forStderr(PrintStream err, double limit) {
            return new Progress(err, limit, stderrIsTerminal());
        }

        private static boolean stderrIsTerminal() {
            try {
                String target = Files.readSymbolicLink(Path.of("/proc/self/fd/2")).toString();
                return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty");
            } catch (Exception e) {
                return false;
            }
        }

        void update(double t) {
            if (!enabled) {
                return;
            }
            long now = System.nanoTime();
            if (now - start < 1_000_000_000L || now - last < 200_000_000L) {
                return;
            }
            last = now;
            shown = true;
            String of = Double.isInfinite(limit) ? "" : String.format(Locale.ROOT, " / %.1f s (%.0f%%)", limit, 100 * t / limit);
            err.print(String.format(Locale.ROOT, "\rparpe: t = %.1f s%s, %.1fx real time   ", t, of,
                    t / ((now - start) / 1e9)));
            err.flush();
        }

        void done() {
            if (shown) {
                err.print("\r" + " ".repeat(60) + "\r");
                err.flush();
            }
        }
    }
}
