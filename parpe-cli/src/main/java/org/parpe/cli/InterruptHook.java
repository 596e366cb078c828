package org.parpe.cli;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.parpe.core.run.Run;

/**
 * Ctrl-C during a run: asks the run to stop at the next tick and holds the JVM's shutdown for
 * up to three seconds so the run can end properly (emergency stop on the bus, trace flushed).
 */
final class InterruptHook implements AutoCloseable {
    private final CountDownLatch done = new CountDownLatch(1);
    private final Thread hook;

    /** Installs the hook for {@code run}; {@link #close()} removes it when the run is over. */
    InterruptHook(Run run) {
        hook = new Thread(() -> {
            run.requestStop();
            try {
                done.await(3, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "parpe-interrupt");
        Runtime.getRuntime().addShutdownHook(hook);
    }

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
