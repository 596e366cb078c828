package org.parpe.cli.hw;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.RunOutcome;
import org.parpe.serial.bus.BusThread;

/**
 * The producer of the driver benchmarks ({@code bench --only serial} and {@code --only servo}),
 * the same for every protocol: a run of {@code n} modules whose setpoints change every 0.5 ms,
 * faster than any line carries them, so the driver's rate is limited by the wire alone.
 */
final class PacedProducer {
    /** Time between two rows of setpoints. */
    private static final long PRODUCER_NANOS = 500_000;
    /** Time before counting starts (classes loaded, the line busy). */
    private static final long WARM_UP_NANOS = 500_000_000L;

    private PacedProducer() {
    }

    /**
     * Starts {@code driver} (discovered already) for modules {@code ids}, feeds it for
     * {@code seconds}, finishes the run and returns how fast {@code delivered} rose after the
     * warm-up, per second.
     */
    static double drive(BusThread driver, int[] ids, double seconds, AtomicLong delivered) {
        int n = ids.length;
        driver.start(new RunInfo(null, ids, 0.01));
        double[] row = new double[n];
        long end = System.nanoTime() + (long) (seconds * 1e9);
        long warm = System.nanoTime() + WARM_UP_NANOS;
        long startCount = -1;
        long start = 0;
        for (long k = 0; System.nanoTime() < end; k++) {
            if (startCount < 0 && System.nanoTime() > warm) {
                startCount = delivered.get();
                start = System.nanoTime();
            }
            row[(int) (k % n)] = (k % 1800) / 20.0 - 45;
            driver.accept(k, k * 0.01, row);
            LockSupport.parkNanos(PRODUCER_NANOS);
        }
        double rate = (delivered.get() - startCount) / ((System.nanoTime() - start) / 1e9);
        driver.finish(new RunOutcome(RunOutcome.Status.COMPLETED, 0, ""));
        return rate;
    }
}
