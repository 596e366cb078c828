package org.parpe.cli;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * Ctrl-C during a command that must end properly (a run: emergency stop on the bus, trace
 * flushed; a sweep: the finished rows written): asks the work to stop and holds the JVM's
 * shutdown for a few seconds until {@link #close()} says the work has ended.
 */
public final class InterruptHook implements AutoCloseable {
    private final CountDownLatch done = new CountDownLatch(1);
    private final Thread hook;
    private volatile boolean interrupted;

    /**
     * Installs the hook: on Ctrl-C, {@code stop} runs (it must only set a flag), then shutdown
     * waits up to {@code holdSeconds} for {@link #close()}.
     */
    public InterruptHook(Runnable stop, int holdSeconds) {
        hook = new Thread(() -> {
            interrupted = true;
            stop.run();
            try {
                done.await(holdSeconds, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "parpe-interrupt");
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /** Whether Ctrl-C was pressed. */
    public boolean interrupted() {
        return interrupted;
    }

    /** The work has ended: shutdown may go on, and without Ctrl-C the hook is removed. */
    @Override
    public void close() {
        done.countDown();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // the JVM is exiting because of Ctrl-C: the hook is running and waits for us
        }
    }
}
