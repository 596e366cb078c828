package org.parpe.cli.sweep;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.parpe.sim.sweep.Cancellation;

/**
 * Ctrl-C during a sweep or an optimisation: cancels it (the runs in progress stop at their next
 * tick) and holds the JVM's shutdown for up to five seconds so the finished rows are written.
 */
final class StopOnInterrupt implements AutoCloseable {
    private final CountDownLatch done = new CountDownLatch(1);
    private final Thread hook;
    private volatile boolean interrupted;

    StopOnInterrupt(Cancellation cancellation) {
        hook = new Thread(() -> {
            interrupted = true;
            cancellation.cancel();
            try {
                done.await(5, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "parpe-interrupt");
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /** Whether Ctrl-C was pressed. */
    boolean interrupted() {
        return interrupted;
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
